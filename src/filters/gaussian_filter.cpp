#include "filters/gaussian_filter.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "filters/filter_params.h"

namespace eyetrace {

namespace {

// Table cells per axis: fine enough for both the radius and sigma (four cells per sigma).
IVec2 table_cells(Vec2 radius, float sigma) {
  auto cells = [&](float r) {
    return std::max(filter_sampling::filter_table_cells(r), std::min(1024, int(std::ceil(4.f * r / sigma))));
  };
  return IVec2(cells(radius.x), cells(radius.y));
}

// The integral of g over [-r, r]: erf(r / (sigma sqrt 2)) - 2 r G(r).
double shifted_gaussian_integral(double r, double sigma) {
  double g_r = std::exp(-r * r / (2.0 * sigma * sigma)) / std::sqrt(2.0 * std::numbers::pi * sigma * sigma);
  return std::erf(r / (sigma * std::sqrt(2.0))) - 2.0 * r * g_r;
}

}  // namespace

// The sampler tabulates evaluate(), so it is built from a filter whose members are set.
GaussianFilter::GaussianFilter(Vec2 radius, float sigma)
    : radius_(radius),
      sigma_(sigma),
      integral_(float(shifted_gaussian_integral(radius.x, sigma) * shifted_gaussian_integral(radius.y, sigma))),
      norm_(1.0 / std::sqrt(std::numbers::pi * (2.0 * double(sigma) * double(sigma)))),
      edge_{std::exp(-double(radius.x) * radius.x / (2.0 * double(sigma) * double(sigma))),
            std::exp(-double(radius.y) * radius.y / (2.0 * double(sigma) * double(sigma)))},
      ratio_step_(std::exp(-1.0 / (double(sigma) * double(sigma)))),
      sampler_(*this, table_cells(radius, sigma), integral_) {}

double GaussianFilter::shifted_gaussian(double x, int axis) const {
  const double r = radius_[axis];
  if (std::abs(x) >= r) return 0.0;
  double s2 = 2.0 * double(sigma_) * double(sigma_);
  double a = (r * r - x * x) / s2;
  // Close to the radius G(x) - G(r) cancels: G(r) (e^a - 1) keeps the digits.
  if (a < 1.0) return norm_ * edge_[axis] * std::expm1(a);
  return norm_ * (std::exp(-x * x / s2) - edge_[axis]);
}

// The row by recurrence, two exponentials for the whole row (the splats' per-tap exp was a tenth
// of a dispersive render's time): with t_i = t0 - i, G(t_{i+1}) = G(t_i) q_i where
// q_i = exp((2 t_i - 1) / s2), and q_{i+1} = q_i exp(-2 / s2). Each step adds a rounding of
// about 1e-16 relative, far below the float result's; near the radius G - G(r) then loses the
// digits expm1 keeps in shifted_gaussian, about 1e-16 absolute. Narrow filters whose ratios
// would overflow take the taps one by one.
void GaussianFilter::evaluate_axis_row(double t0, int n, int axis, float* out) const {
  const double s2 = 2.0 * double(sigma_) * double(sigma_);
  const double r = radius_[axis];
  const double q_exponent = (2.0 * t0 - 1.0) / s2;
  // G(t0) must not underflow (G rises towards the peak from there), nor q overflow.
  if (!(t0 * t0 / s2 < 600.0 && std::abs(q_exponent) < 600.0 && 2.0 * n / s2 < 600.0))
    return Filter::evaluate_axis_row(t0, n, axis, out);
  double g = std::exp(-t0 * t0 / s2), q = std::exp(q_exponent);
  for (int i = 0; i < n; ++i) {
    const double t = t0 - i;
    out[i] = std::abs(t) < r ? float(norm_ * std::max(0.0, g - edge_[axis])) : 0.f;
    g *= q;
    q *= ratio_step_;
  }
}

float GaussianFilter::evaluate(Vec2 p) const { return float(shifted_gaussian(p.x, 0) * shifted_gaussian(p.y, 1)); }

std::string GaussianFilter::to_string() const {
  return fmt::format("GaussianFilter[xradius={} yradius={} sigma={}]", radius_.x, radius_.y, sigma_);
}

float GaussianFilter::min_sigma(Vec2 radius) { return std::max(radius.x, radius.y) / 256.f; }

const PluginSpec& gaussian_filter_spec() {
  static const PluginSpec spec{
      "PixelFilter", "a Gaussian, shifted to reach zero at the radius", "—",
      filter_radius_params(1.5) +
          std::vector<ParamSpec>{
              param::real("sigma", 0.5).with_unit("pixels").describe("standard deviation, at least radius/256")}};
  return spec;
}

std::unique_ptr<Filter> create_gaussian_filter(const ParameterList& list) {
  const PluginParams params(list, gaussian_filter_spec(), "gaussian");
  Vec2 radius = read_filter_radius(params);
  float sigma = params.get_float("sigma");
  if (!(sigma >= GaussianFilter::min_sigma(radius)))
    params.fail("sigma", fmt::format("value {} must be at least radius / 256 = {} (for a narrower filter use a "
                                     "smaller radius or the box filter)",
                                     sigma, GaussianFilter::min_sigma(radius)));
  return std::make_unique<GaussianFilter>(radius, sigma);
}

}  // namespace eyetrace
