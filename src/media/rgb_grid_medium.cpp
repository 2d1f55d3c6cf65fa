#include "media/rgb_grid_medium.h"

#include <algorithm>
#include <cmath>

#include "core/spectrum.h"
#include "media/medium_params.h"

namespace eyetrace {

RgbSpectrumSample RgbSpectrumSample::from_rgb(const RGB& rgb, bool illuminant) {
  // pbrt-v4's RGBUnboundedSpectrum and RGBIlluminantSpectrum: the sigmoid fitted to rgb / 2m.
  RgbSpectrumSample s;
  s.times_white = illuminant;
  const float m = std::max({rgb.r, rgb.g, rgb.b});
  if (!(m > 0.f)) return s;
  s.scale = 2.f * m;
  s.poly = RGBToSpectrumTable::srgb()(rgb / s.scale);
  return s;
}

SampledSpectrum RgbSpectrumSample::sample(const SampledWavelengths& lambda) const {
  SampledSpectrum v(0.f);
  if (scale == 0.f) return v;
  for (int i = 0; i < kSpectrumSamples; ++i)
    v[i] = scale * poly(lambda[i]) * (times_white ? white_illuminant(lambda[i]) : 1.f);
  return v;
}

RGBGridMedium::RGBGridMedium(MediumBox box, float g, std::optional<Grid> sigma_a, std::optional<Grid> sigma_s,
                             float sigma_scale, std::optional<Grid> Le, float Le_scale)
    : box_(std::move(box)),
      g_(g),
      sigma_a_(std::move(sigma_a)),
      sigma_s_(std::move(sigma_s)),
      Le_(std::move(Le)),
      sigma_scale_(sigma_scale),
      Le_scale_(Le_scale) {
  majorant_grid_.bounds = box_.bounds;
  const int n = majorant_grid_.res;
  auto max = [](const RgbSpectrumSample& s) { return s.max_value(); };
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Bounds3 b = majorant_grid_.voxel_bounds(x, y, z);
        const float a = sigma_a_ ? sigma_a_->max_value(b, max) : 1.f;
        const float s = sigma_s_ ? sigma_s_->max_value(b, max) : 1.f;
        majorant_grid_.set(x, y, z, sigma_scale_ * (a + s));
      }
}

MediumProperties RGBGridMedium::properties(const Vec3& p, const SampledWavelengths& lambda) const {
  const Vec3 unit = box_.to_unit(box_.to_medium(p));
  auto convert = [&](const RgbSpectrumSample& s) { return s.sample(lambda); };
  MediumProperties mp;
  mp.sigma_a = sigma_scale_ * (sigma_a_ ? sigma_a_->lookup(unit, convert) : SampledSpectrum(1.f));
  mp.sigma_s = sigma_scale_ * (sigma_s_ ? sigma_s_->lookup(unit, convert) : SampledSpectrum(1.f));
  mp.Le = SampledSpectrum(0.f);
  // pbrt-v4's film reads Y as the integral of y-bar L without dividing by the y-bar integral,
  // and this emission is not normalised to luminance (unlike lights and the other media's
  // Le): multiplied by that integral for eyetrace's film to show pbrt-v4's image.
  if (emissive()) mp.Le = Le_scale_ * cie_y_integral() * Le_->lookup(unit, convert);
  mp.g = g_;
  return mp;
}

MajorantIterator RGBGridMedium::majorants(const Ray& ray, float t_max, const SampledWavelengths&) const {
  const auto c = box_.clip(ray, t_max);
  if (!c) return MajorantIterator();
  return MajorantIterator(c->o, c->d, c->t0, c->t1, &majorant_grid_, SampledSpectrum(1.f));
}

const PluginSpec& rgb_grid_medium_spec() {
  static const PluginSpec spec{
      "MakeNamedMedium",
      "RGB absorption, scattering and emission on a grid (trilinear)",
      "—",
      {param::rgbs("sigma_a").describe("nx*ny*nz RGB absorption coefficients (absent: 1 everywhere)"),
       param::rgbs("sigma_s").describe("nx*ny*nz RGB scattering coefficients (absent: 1 everywhere)"),
       param::rgbs("Le").describe("nx*ny*nz RGB emitted radiances (needs `sigma_a`)"),
       param::integer("nx", 1).at_least(1).describe("grid samples along x"),
       param::integer("ny", 1).at_least(1).describe("grid samples along y"),
       param::integer("nz", 1).at_least(1).describe("grid samples along z"),
       param::point3("p0", Vec3(0.f)).describe("the grid's lower corner, in the medium's space"),
       param::point3("p1", Vec3(1.f)).describe("the grid's upper corner, in the medium's space"),
       param::real("scale", 1).at_least(0).describe("multiplies `sigma_a` and `sigma_s`"),
       param::real("Lescale", 1).at_least(0).describe("multiplies `Le`"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1)")}};
  return spec;
}

namespace {

std::optional<RGBGridMedium::Grid> rgb_grid_param(const PluginParams& p, const std::string& name, int nx, int ny,
                                                  int nz, bool illuminant) {
  if (!p.has(name)) return std::nullopt;
  const std::vector<RGB> rgbs = p.get_rgbs(name);
  const size_t n = size_t(nx) * ny * nz;
  if (rgbs.size() != n)
    p.fail(name, fmt::format("has {} RGB values; nx*ny*nz = {}*{}*{} = {} expected", rgbs.size(), nx, ny, nz, n));
  std::vector<RgbSpectrumSample> samples;
  samples.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    const RGB& c = rgbs[i];
    if (!(c.r >= 0.f && c.g >= 0.f && c.b >= 0.f))
      p.fail(name, fmt::format("value {} (x {}, y {}, z {}) is ({}, {}, {}): no component may be negative", i, i % nx,
                               (i / nx) % ny, i / (size_t(nx) * ny), c.r, c.g, c.b));
    samples.push_back(RgbSpectrumSample::from_rgb(c, illuminant));
  }
  return RGBGridMedium::Grid(std::move(samples), nx, ny, nz);
}

}  // namespace

std::unique_ptr<Medium> create_rgb_grid_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, rgb_grid_medium_spec(), "rgbgrid");
  if (!p.has("sigma_a") && !p.has("sigma_s"))
    p.fail("sigma_a", "and \"sigma_s\" are both absent: an rgbgrid needs at least one of them");
  if (p.has("Le") && !p.has("sigma_a")) p.fail("Le", "needs \"sigma_a\" (emission is per unit of absorption)");
  const int nx = p.get_int("nx"), ny = p.get_int("ny"), nz = p.get_int("nz");
  if (double(nx) * ny * nz > 1e9) p.fail("nx", fmt::format("{}*{}*{} samples is more than 10^9", nx, ny, nz));
  auto sigma_a = rgb_grid_param(p, "sigma_a", nx, ny, nz, false);
  auto sigma_s = rgb_grid_param(p, "sigma_s", nx, ny, nz, false);
  auto Le = rgb_grid_param(p, "Le", nx, ny, nz, true);
  MediumBox box{medium_bounds_param(p), ctx.world_from_medium.inverse()};
  return std::make_unique<RGBGridMedium>(std::move(box), asymmetry_param(p), std::move(sigma_a), std::move(sigma_s),
                                         p.get_float("scale"), std::move(Le), p.get_float("Lescale"));
}

}  // namespace eyetrace
