#include "filters/sinc_filter.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "filters/filter_params.h"

namespace eyetrace {

double SincFilter::sinc(double x) {
  const double px = std::numbers::pi * x;
  // Near 0 the quotient loses its digits; two terms of the series are exact to double there.
  if (std::abs(px) < 1e-4) return 1.0 - px * px / 6.0;
  return std::sin(px) / px;
}

double SincFilter::windowed_sinc(double x, double radius, double tau) {
  if (std::abs(x) > radius) return 0.0;
  return sinc(x) * sinc(x / tau);
}

double SincFilter::windowed_sinc_integral(double radius, double tau) {
  const int n = 2 * std::max(1, int(std::ceil(1024.0 * radius)));  // even, for Simpson
  const double h = 2.0 * radius / n;
  double sum = windowed_sinc(-radius, radius, tau) + windowed_sinc(radius, radius, tau);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * windowed_sinc(-radius + i * h, radius, tau);
  return sum * h / 3.0;
}

// Members used by evaluate() are set before the sampler tabulates it.
SincFilter::SincFilter(Vec2 radius, float tau)
    : radius_(radius),
      tau_(tau),
      integral_(float(windowed_sinc_integral(radius.x, tau) * windowed_sinc_integral(radius.y, tau))),
      sampler_(*this,
               IVec2(filter_sampling::filter_table_cells(radius.x), filter_sampling::filter_table_cells(radius.y)),
               integral_) {}

std::string SincFilter::to_string() const {
  return fmt::format("SincFilter[xradius={} yradius={} tau={}]", radius_.x, radius_.y, tau_);
}

const PluginSpec& sinc_filter_spec() {
  static const PluginSpec spec{
      "PixelFilter", "a sinc windowed by a wider sinc (Lanczos), with negative lobes",
      "Sampled as pbrt-v4 samples it, from a table of the filter's magnitude with signed weights; each weight is "
      "the exact filter value at the sample over its density (pbrt-v4: the table cell's value), so the filter is not "
      "quantised to the table's cells.",
      filter_radius_params(4) + std::vector<ParamSpec>{param::real("tau", 3).range(1e-2, 1e3).describe(
                                    "width of the window sinc, in its zero crossings")}};
  return spec;
}

std::unique_ptr<Filter> create_sinc_filter(const ParameterList& list) {
  const PluginParams params(list, sinc_filter_spec(), "sinc");
  const Vec2 radius = read_filter_radius(params);
  const float tau = params.get_float("tau");
  auto filter = std::make_unique<SincFilter>(radius, tau);
  // A radius that ends where the lobes cancel leaves a filter with no weight to normalise by.
  if (!(filter->integral() > 1e-3f * radius.x * radius.y))
    params.fail("tau", fmt::format("with radius ({}, {}) the filter integrates to {}: no usable weight", radius.x,
                                   radius.y, filter->integral()));
  return filter;
}

}  // namespace eyetrace
