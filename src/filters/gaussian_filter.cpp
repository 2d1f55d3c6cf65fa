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

// Segments of the row table (AxisFactorTable): 16 per sigma, so its error bound, 5.1e-4 h^4 times
// the largest fourth derivative of g, 3 g(0) / sigma^4, is 2.3e-8 g(0); at least 64.
int row_segments(float radius, float sigma) { return std::max(64, int(std::ceil(16.f * radius / sigma))); }

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
      sampler_(*this, table_cells(radius, sigma), integral_) {
  for (int axis = 0; axis < 2; ++axis)
    rows_[axis] = AxisFactorTable([this, axis](double t) { return shifted_gaussian(t, axis); }, radius_[axis],
                                  row_segments(radius_[axis], sigma));
}

double GaussianFilter::shifted_gaussian(double x, int axis) const {
  const double r = radius_[axis];
  if (std::abs(x) >= r) return 0.0;
  double s2 = 2.0 * double(sigma_) * double(sigma_);
  double a = (r * r - x * x) / s2;
  // Close to the radius G(x) - G(r) cancels: G(r) (e^a - 1) keeps the digits.
  if (a < 1.0) return norm_ * edge_[axis] * std::expm1(a);
  return norm_ * (std::exp(-x * x / s2) - edge_[axis]);
}

// The row from the piecewise-cubic table of g (16 segments per sigma: within 2.3e-8 of g(0), below
// the float result's rounding): the exact g takes an exp per tap, a tenth of a dispersive
// render's time when every wavelength splatted that way.
void GaussianFilter::evaluate_axis_row(double t0, int n, int axis, float* out) const { rows_[axis].row(t0, n, out); }

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
