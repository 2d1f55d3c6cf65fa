#include "media/grid_medium.h"

#include <cmath>

#include "lights/light_params.h"
#include "media/medium_params.h"

namespace eyetrace {

float normalized_blackbody(float lambda_nm, float kelvin) {
  if (!(kelvin > 0.f)) return 0.f;
  const double peak_nm = 2.8977721e-3 / kelvin * 1e9;
  return float(planck(lambda_nm, kelvin) / planck(peak_nm, kelvin));
}

GridMedium::GridMedium(MediumBox box, Spectrum sigma_a, Spectrum sigma_s, float g, SampledGrid<float> density,
                       Emission emission)
    : box_(std::move(box)),
      sigma_a_(std::move(sigma_a)),
      sigma_s_(std::move(sigma_s)),
      g_(g),
      density_(std::move(density)),
      emission_(std::move(emission)) {
  emissive_ = emission_.temperature.has_value();
  for (float l = kLambdaMin; l <= kLambdaMax && !emissive_; l += 1.f) emissive_ = emission_.Le(l) > 0.f;
  majorant_grid_.bounds = box_.bounds;
  const int n = majorant_grid_.res;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        majorant_grid_.set(x, y, z,
                           density_.max_value(majorant_grid_.voxel_bounds(x, y, z), [](float v) { return v; }));
}

SampledSpectrum GridMedium::emission(const Vec3& unit, const SampledWavelengths& lambda) const {
  const float scale = emission_.Le_scale.lookup(unit);
  if (!(scale > 0.f)) return SampledSpectrum(0.f);
  if (!emission_.temperature) return scale * emission_.Le.sample(lambda);
  const float kelvin =
      (emission_.temperature->lookup(unit) - emission_.temperature_offset) * emission_.temperature_scale;
  if (!(kelvin > 100.f)) return SampledSpectrum(0.f);
  // pbrt-v4's film reads radiance L as Y = integral of y-bar L (its sensor does not divide by
  // the y-bar integral); eyetrace's divides, so a spectrum not normalised to luminance, as this
  // one, is multiplied by that integral to give pbrt-v4's image (lights are normalised, and
  // agree without it).
  const float to_pbrt_film = scale * cie_y_integral();
  SampledSpectrum Le;
  for (int i = 0; i < kSpectrumSamples; ++i) Le[i] = to_pbrt_film * normalized_blackbody(lambda[i], kelvin);
  return Le;
}

MediumProperties GridMedium::properties(const Vec3& p, const SampledWavelengths& lambda) const {
  const Vec3 unit = box_.to_unit(box_.to_medium(p));
  const float d = density_.lookup(unit);
  MediumProperties mp{sigma_a_.sample(lambda) * d, sigma_s_.sample(lambda) * d, SampledSpectrum(0.f), g_};
  if (emissive_) mp.Le = emission(unit, lambda);
  return mp;
}

MajorantIterator GridMedium::majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const {
  const auto c = box_.clip(ray, t_max);
  if (!c) return MajorantIterator();
  return MajorantIterator(c->o, c->d, c->t0, c->t1, &majorant_grid_, sigma_a_.sample(lambda) + sigma_s_.sample(lambda));
}

const PluginSpec& grid_medium_spec() {
  static const PluginSpec spec{
      "MakeNamedMedium",
      "density on a grid (trilinear) scaling sigma_a and sigma_s; emission from Le or a temperature grid",
      "—",
      {param::reals("density").describe("nx*ny*nz densities, x fastest, then y, then z (required, >= 0)"),
       param::integer("nx", 1).at_least(1).describe("grid samples along x"),
       param::integer("ny", 1).at_least(1).describe("grid samples along y"),
       param::integer("nz", 1).at_least(1).describe("grid samples along z"),
       param::point3("p0", Vec3(0.f)).describe("the grid's lower corner, in the medium's space"),
       param::point3("p1", Vec3(1.f)).describe("the grid's upper corner, in the medium's space"),
       param::spectrum("sigma_a", 1).describe("absorption coefficient at density 1, per unit length"),
       param::spectrum("sigma_s", 1).describe("scattering coefficient at density 1, per unit length"),
       param::real("scale", 1).at_least(0).describe("multiplies `sigma_a` and `sigma_s`"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1)"),
       param::spectrum("Le").describe("emitted radiance (illuminant spectrum), per unit of sigma_a; not with "
                                      "`temperature`"),
       param::reals("Lescale").describe("nx*ny*nz values: a grid multiplying the emission (default: one "
                                        "sample of 1 at the box's centre, which fades towards its faces)"),
       param::reals("temperature").describe("nx*ny*nz temperatures: blackbody emission (peak 1)"),
       param::real("temperatureoffset").describe("subtracted from `temperature` (default `temperaturecutoff`)"),
       param::real("temperaturecutoff", 0).describe("pbrt-v4's older name for `temperatureoffset`"),
       param::real("temperaturescale", 1).describe("multiplies the offset temperature, giving kelvin")}};
  return spec;
}

namespace {

// A grid parameter: exactly nx*ny*nz finite values, none negative.
SampledGrid<float> grid_param(const PluginParams& p, const std::string& name, int nx, int ny, int nz) {
  std::vector<float> v = p.get_floats(name);
  const size_t n = size_t(nx) * ny * nz;
  if (v.size() != n)
    p.fail(name, fmt::format("has {} values; nx*ny*nz = {}*{}*{} = {} expected", v.size(), nx, ny, nz, n));
  for (size_t i = 0; i < n; ++i)
    if (!(v[i] >= 0.f) || !std::isfinite(v[i]))
      p.fail(name, fmt::format("value {} (x {}, y {}, z {}) is {}: must be finite and not negative", i, i % nx,
                               (i / nx) % ny, i / (size_t(nx) * ny), v[i]));
  return SampledGrid<float>(std::move(v), nx, ny, nz);
}

}  // namespace

std::unique_ptr<Medium> create_grid_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, grid_medium_spec(), "uniformgrid");
  if (!p.has("density")) p.fail("density", "is required: the grid's nx*ny*nz densities");
  const int nx = p.get_int("nx"), ny = p.get_int("ny"), nz = p.get_int("nz");
  if (double(nx) * ny * nz > 1e9) p.fail("nx", fmt::format("{}*{}*{} samples is more than 10^9", nx, ny, nz));
  SampledGrid<float> density = grid_param(p, "density", nx, ny, nz);
  const float scale = p.get_float("scale");
  GridMedium::Emission e;
  if (p.has("temperature")) {
    if (p.has("Le")) p.fail("Le", "and \"temperature\" are both given: the emission is one or the other");
    e.temperature = grid_param(p, "temperature", nx, ny, nz);
    e.temperature_offset =
        p.has("temperatureoffset") ? p.get_float("temperatureoffset") : p.get_float("temperaturecutoff");
    e.temperature_scale = p.get_float("temperaturescale");
  }
  // pbrt-v4 normalises Le to luminance 1 (as an area light's L) through the Lescale grid.
  const std::optional<Spectrum> Le = emission_param_or_null(p, "Le");
  if (Le) e.Le = *Le;
  if (!p.has("Lescale")) {
    e.Le_scale = SampledGrid<float>({1.f}, 1, 1, 1);  // as pbrt-v4: one sample, so it fades at the edges
  } else {
    e.Le_scale = grid_param(p, "Lescale", nx, ny, nz);
  }
  MediumBox box{medium_bounds_param(p), ctx.world_from_medium.inverse()};
  return std::make_unique<GridMedium>(std::move(box), coefficient_param(p, "sigma_a").scaled(scale),
                                      coefficient_param(p, "sigma_s").scaled(scale), asymmetry_param(p),
                                      std::move(density), std::move(e));
}

}  // namespace eyetrace
