#include "cameras/wave_psf_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/chromatic.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/psf_image.h"
#include "optics/wavefront.h"

namespace eyetrace {

namespace {

// Wavelength nodes of a dispersive eye: from 400 nm to the top of the range the renderer
// samples (core/sampled_spectrum.h), a node wherever the eye's chromatic refraction has changed
// by kNodeRefraction_D since the last one (scanned every 5 nm): the PSF changes with
// wavelength mostly through that defocus, fastest in the blue. 0.25 D is 0.05 waves RMS over
// a 2 mm pupil at 550 nm. Navarro: 13 nodes. Below 400 nm the relaxed Navarro eye is more
// than 2 D myopic, its blur geometric, and its wave PSFs would need pupil grids (and FFTs)
// several times larger: rays there keep their traced direction. Above the last node the PSF
// of the last is used.
constexpr double kLambdaLo_nm = 400.0, kLambdaHi_nm = 830.0, kLambdaScan_nm = 5.0;
constexpr double kNodeRefraction_D = 0.25;
// The pupil grid starts at the wave report's default and is refined, as the report does
// (optics/wave_optics_report.cpp), until neighbouring pupil samples differ by at most pi/2 of
// phase, up to kMaxGrid; a node still coarser than that would wrap its PSF and is left
// geometric.
constexpr int kStartGrid = 64, kMaxGrid = 256;
constexpr double kMaxPhaseStep_rad = 0.5 * std::numbers::pi;

optics::PsfImage node_psf(const optics::Prescription& p, optics::WavefrontOptions o) {
  optics::PsfImage psf = optics::psf_image(optics::trace_wavefront(p, o));
  while (psf.max_phase_step_rad > kMaxPhaseStep_rad && o.grid < kMaxGrid) {
    const double needed = o.grid * psf.max_phase_step_rad / kMaxPhaseStep_rad;
    o.grid = std::min(kMaxGrid, 16 * static_cast<int>(std::ceil(needed / 16.0)));
    psf = optics::psf_image(optics::trace_wavefront(p, o));
  }
  return psf;
}

// Half-width h (samples) of the smallest square about the centre holding `fraction` of the
// energy, growing it ring by ring.
int crop_half_width(const optics::PsfImage& psf, double fraction) {
  const int n = psf.fft_size, c = n / 2;
  double total = 0.0;
  for (double v : psf.intensity) total += v;
  double inside = psf.at(c, c);
  int h = 0;
  while (inside < fraction * total && h < c - 1) {
    ++h;
    for (int i = -h; i <= h; ++i) {
      inside += psf.at(c + i, c - h) + psf.at(c + i, c + h);
      if (i != -h && i != h) inside += psf.at(c - h, c + i) + psf.at(c + h, c + i);
    }
  }
  return h;
}

}  // namespace

WavePsfTable::WavePsfTable(const optics::Prescription& prescription, const optics::Prescription& aiming,
                           const RetinaSurface& retina, double z_plane, double max_arc_mm, const Options& options) {
  if (options.dispersive) {
    auto refraction = [&](double lambda) {
      return optics::paraxial_analysis(optics::at_wavelength(prescription, lambda)).refraction_D;
    };
    lambdas_.push_back(kLambdaLo_nm);
    double last = refraction(kLambdaLo_nm);
    for (double lambda = kLambdaLo_nm + kLambdaScan_nm; lambda < kLambdaHi_nm; lambda += kLambdaScan_nm) {
      const double r = refraction(lambda);
      if (std::abs(r - last) >= kNodeRefraction_D) lambdas_.push_back(lambda), last = r;
    }
    lambdas_.push_back(kLambdaHi_nm);
  } else {
    lambdas_.push_back(prescription.wavelength_nm);
  }
  const double max_field = std::max(options.max_field_deg, 0.0);
  field_nodes_ = static_cast<int>(std::ceil(max_field / kFieldStep_deg)) + 1;
  entrance_pupil_z_mm_ = optics::paraxial_analysis(prescription).entrance_pupil.position_mm;
  focus_distance_mm_ = options.focus_distance_m > 0.0 ? options.focus_distance_m * 1e3 : 0.0;
  for (double lambda : lambdas_) {
    const optics::CompiledSystem system(optics::at_wavelength(aiming, lambda));
    angles_.emplace_back(system, retina, z_plane, max_field + kFieldStep_deg, max_arc_mm);
  }
  nodes_.resize(lambdas_.size() * size_t(field_nodes_));
  tbb::parallel_for(size_t(0), nodes_.size(), [&](size_t k) {
    build_node(prescription, int(k % size_t(field_nodes_)), int(k / size_t(field_nodes_)), &nodes_[k]);
  });
  geometric_beyond_deg_ = -1.0;
  for (size_t k = 0; k < nodes_.size(); ++k)
    if (!nodes_[k].ok) {
      const double field = double(k % size_t(field_nodes_)) * kFieldStep_deg;
      if (geometric_beyond_deg_ < 0.0 || field < geometric_beyond_deg_) geometric_beyond_deg_ = field;
    }
  if (geometric_beyond_deg_ == 0.0)
    throw optics::OpticsError("diffraction: the wave PSF on the axis cannot be computed for this eye");
}

void WavePsfTable::build_node(const optics::Prescription& p, int field, int wavelength, Node* node) const {
  optics::WavefrontOptions o;
  o.field_deg = field * kFieldStep_deg;
  o.wavelength_nm = lambdas_[size_t(wavelength)];
  if (focus_distance_mm_ > 0.0) o.object_distance_m = focus_distance_mm_ * 1e-3;
  o.clip_at_stop = true;  // the real iris is the pupil
  o.grid = kStartGrid;
  o.zernike_order = 2;  // the PSF needs the OPD only
  optics::PsfImage psf;
  try {
    psf = node_psf(p, o);
  } catch (const optics::OpticsError&) {
    return;  // node->ok stays false: rays there keep their geometric direction
  }
  if (psf.max_phase_step_rad > std::numbers::pi) return;  // even at kMaxGrid: the PSF would wrap
  const int h = crop_half_width(psf, kKeptEnergy), c = psf.fft_size / 2;
  node->size = 2 * h + 1;
  node->origin = -h;
  node->sample_x_rad = psf.sample_x_rad;
  node->sample_y_rad = psf.sample_y_rad;
  node->cdf.resize(size_t(node->size) * size_t(node->size));
  double sum = 0.0;
  for (int y = 0; y < node->size; ++y)
    for (int x = 0; x < node->size; ++x) {
      sum += std::max(psf.at(c - h + x, c - h + y), 0.0);
      node->cdf[size_t(y) * size_t(node->size) + size_t(x)] = float(sum);
    }
  if (!(sum > 0.0)) return;
  for (float& v : node->cdf) v = float(v / sum);
  node->cdf.back() = 1.f;
  node->ok = true;
}

// A sample of the node's PSF by its CDF, then uniform within the sample's cell: (sagittal,
// tangential) angle, radians. The cell's width (lambda / 4D at the automatic FFT size) widens
// the PSF by its variance, 1/12 of a cell squared per axis.
glm::dvec2 WavePsfTable::sample_node(const Node& n, const double u[3]) const {
  const auto it = std::upper_bound(n.cdf.begin(), n.cdf.end(), float(u[0]));
  const size_t k = std::min(size_t(it - n.cdf.begin()), n.cdf.size() - 1);
  const int iy = int(k / size_t(n.size)), ix = int(k % size_t(n.size));
  return {(n.origin + ix + u[1] - 0.5) * n.sample_x_rad, (n.origin + iy + u[2] - 0.5) * n.sample_y_rad};
}

WavePsfTable::Sample WavePsfTable::sample(double arc_mm, double lambda_nm, const double u[5]) const {
  Sample s;
  size_t j = 0;
  if (lambdas_.size() > 1) {
    if (lambda_nm < lambdas_.front()) return s;  // geometric (see kLambdaLo_nm)
    const double lambda = std::min(lambda_nm, lambdas_.back());
    j = std::min(size_t(std::upper_bound(lambdas_.begin(), lambdas_.end(), lambda) - lambdas_.begin()),
                 lambdas_.size() - 1) -
        1;
    const double t = (lambda - lambdas_[j]) / (lambdas_[j + 1] - lambdas_[j]);
    if (u[3] < t) ++j;  // the nearer node more often: linear interpolation in lambda
  }
  double slope = 0.0;
  const double field = angles_[j].angle_for_arc(arc_mm, &slope);
  if (!(field >= 0.0)) return s;
  const double x = field / kFieldStep_deg;
  size_t i = size_t(x);
  if (u[4] < x - double(i)) ++i;
  if (i >= size_t(field_nodes_)) return s;
  const Node& n = nodes_[j * size_t(field_nodes_) + i];
  if (!n.ok) return s;
  s.field_deg = field;
  s.angle_rad = sample_node(n, u);
  s.ok = true;
  return s;
}

std::string WavePsfTable::describe() const {
  size_t floats = 0;
  for (const Node& n : nodes_) floats += n.cdf.size();
  return fmt::format(
      "wave PSF on {} fields (every {} deg) x {} wavelengths, {:.1f} MB{}", field_nodes_, kFieldStep_deg,
      lambdas_.size(), floats * 4e-6,
      geometric_beyond_deg_ >= 0.0 ? fmt::format(", geometric beyond {} deg", geometric_beyond_deg_) : std::string());
}

}  // namespace eyetrace
