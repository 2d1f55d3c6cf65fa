#include "materials/measured_brdf.h"

#include <cmath>
#include <map>
#include <mutex>

#include <fmt/format.h>

#include "core/constants.h"

namespace eyetrace {

namespace {

const TensorField& field(const TensorFile& file, const std::string& name) {
  if (const TensorField* f = file.find(name)) return *f;
  if (name == "spectra" && file.find("rgb"))
    throw TensorFileError(
        "has an \"rgb\" field but no \"spectra\": RGB measured files are not read (pbrt-v4 does not read them either)");
  throw TensorFileError(fmt::format("has no field \"{}\" (an RGL measured BRDF needs it)", name));
}

// `f` must be of `type` and rank `rank`.
const TensorField& typed(const TensorFile& file, const std::string& name, TensorField::Type type, size_t rank) {
  const TensorField& f = field(file, name);
  if (f.dtype != type || f.shape.size() != rank)
    throw TensorFileError(
        fmt::format("field \"{}\" is {}; expected {} of rank {}", name, f.describe(), tensor_type_name(type), rank));
  return f;
}

void expect_size(const TensorField& f, const std::string& name, size_t dim, uint64_t n, const std::string& what) {
  if (f.shape[dim] != n)
    throw TensorFileError(fmt::format("field \"{}\" ({}) has size {} in dimension {}; expected {} ({})", name,
                                      f.describe(), f.shape[dim], dim, n, what));
}

// Finite values, at least `lo` (or above it when `strict`).
std::vector<float> values(const TensorField& f, const std::string& name, float lo, bool strict) {
  std::vector<float> v = f.floats();
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || v[i] < lo || (strict && v[i] == lo))
      throw TensorFileError(fmt::format("field \"{}\" has the value {} at element {}; its values must be finite{}",
                                        name, v[i], i,
                                        std::isinf(lo) ? "" : fmt::format(" and {} {}", strict ? ">" : ">=", lo)));
  return v;
}

// Parameter nodes: a non-empty, strictly increasing list.
std::vector<float> nodes(const TensorFile& file, const std::string& name) {
  const TensorField& f = typed(file, name, TensorField::Float32, 1);
  std::vector<float> v = values(f, name, -kInfinity, false);
  if (v.empty()) throw TensorFileError(fmt::format("field \"{}\" is empty", name));
  for (size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1]))
      throw TensorFileError(fmt::format("field \"{}\" is not increasing ({} then {})", name, v[i - 1], v[i]));
  return v;
}

// The last two dimensions of a table: at least 2 x 2 for bilinear interpolation.
void expect_grid(const TensorField& f, const std::string& name) {
  const size_t r = f.shape.size();
  if (f.shape[r - 1] < 2 || f.shape[r - 2] < 2)
    throw TensorFileError(fmt::format("field \"{}\" ({}) needs a grid of at least 2 x 2", name, f.describe()));
}

// A warp's slices must each hold some mass, or its CDFs would divide by zero.
void expect_mass(const std::vector<float>& v, size_t slice_size, const std::string& name) {
  for (size_t s = 0; s * slice_size < v.size(); ++s) {
    bool any = false;
    for (size_t i = 0; i < slice_size && !any; ++i) any = v[s * slice_size + i] > 0.f;
    if (!any) throw TensorFileError(fmt::format("field \"{}\" is zero everywhere in slice {}", name, s));
  }
}

}  // namespace

std::shared_ptr<const MeasuredBRDF> make_measured_brdf(const TensorFile& file) {
  typed(file, "description", TensorField::UInt8, 1);
  const TensorField& jacobian = typed(file, "jacobian", TensorField::UInt8, 1);
  expect_size(jacobian, "jacobian", 0, 1, "one flag");
  const std::vector<float> theta_i = nodes(file, "theta_i"), phi_i = nodes(file, "phi_i");
  auto brdf = std::make_shared<MeasuredBRDF>();
  brdf->wavelengths = nodes(file, "wavelengths");

  const TensorField& ndf = typed(file, "ndf", TensorField::Float32, 2);
  const TensorField& sigma = typed(file, "sigma", TensorField::Float32, 2);
  const TensorField& vndf = typed(file, "vndf", TensorField::Float32, 4);
  const TensorField& luminance = typed(file, "luminance", TensorField::Float32, 4);
  const TensorField& spectra = typed(file, "spectra", TensorField::Float32, 5);
  for (auto [f, name] : {std::pair{&ndf, "ndf"}, {&sigma, "sigma"}, {&vndf, "vndf"}, {&luminance, "luminance"}})
    expect_grid(*f, name);
  expect_grid(spectra, "spectra");
  for (auto [f, name] : {std::pair{&vndf, "vndf"}, {&luminance, "luminance"}, {&spectra, "spectra"}}) {
    expect_size(*f, name, 0, phi_i.size(), "the phi_i nodes");
    expect_size(*f, name, 1, theta_i.size(), "the theta_i nodes");
  }
  expect_size(spectra, "spectra", 2, brdf->wavelengths.size(), "the wavelengths");
  // The luminance drives sampling over the same square the spectra tabulate.
  expect_size(luminance, "luminance", 2, spectra.shape[3], "spectra's grid");
  expect_size(luminance, "luminance", 3, spectra.shape[4], "spectra's grid");

  brdf->isotropic = phi_i.size() <= 2;
  if (!brdf->isotropic) {
    // pbrt-v4 reads only files whose phi_i nodes span the whole circle (no symmetry reduction).
    const long reduction = std::lrint(2.0 * kPi / (phi_i.back() - phi_i.front()));
    if (reduction != 1)
      throw TensorFileError(fmt::format(
          "phi_i spans 1/{} of the circle; only files covering all of it are read (as by pbrt-v4)", reduction));
  }

  const std::vector<std::vector<float>> incident{phi_i, theta_i};
  const std::vector<float> ndf_v = values(ndf, "ndf", 0.f, false), sigma_v = values(sigma, "sigma", 0.f, true);
  const std::vector<float> vndf_v = values(vndf, "vndf", 0.f, false);
  const std::vector<float> lum_v = values(luminance, "luminance", 0.f, false);
  const std::vector<float> spectra_v = values(spectra, "spectra", -kInfinity, false);
  expect_mass(vndf_v, vndf.shape[2] * vndf.shape[3], "vndf");
  expect_mass(lum_v, luminance.shape[2] * luminance.shape[3], "luminance");

  auto dims = [](const TensorField& f) {
    const size_t r = f.shape.size();
    return std::pair{int(f.shape[r - 1]), int(f.shape[r - 2])};  // nx (fastest), ny
  };
  auto [ndf_x, ndf_y] = dims(ndf);
  auto [sig_x, sig_y] = dims(sigma);
  auto [vndf_x, vndf_y] = dims(vndf);
  auto [lum_x, lum_y] = dims(luminance);
  brdf->ndf = PiecewiseLinear2D(ndf_v.data(), ndf_x, ndf_y, {}, false);
  brdf->sigma = PiecewiseLinear2D(sigma_v.data(), sig_x, sig_y, {}, false);
  brdf->vndf = PiecewiseLinear2D(vndf_v.data(), vndf_x, vndf_y, incident, true);
  brdf->luminance = PiecewiseLinear2D(lum_v.data(), lum_x, lum_y, incident, true);
  brdf->spectra = PiecewiseLinear2D(spectra_v.data(), lum_x, lum_y, {phi_i, theta_i, brdf->wavelengths}, false);
  return brdf;
}

std::shared_ptr<const MeasuredBRDF> load_measured_brdf(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const MeasuredBRDF>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  if (std::shared_ptr<const MeasuredBRDF> brdf = cache[path].lock()) return brdf;
  std::shared_ptr<const MeasuredBRDF> brdf = make_measured_brdf(read_tensor_file(path));
  cache[path] = brdf;
  return brdf;
}

}  // namespace eyetrace
