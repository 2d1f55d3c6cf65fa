#include "filters/mitchell_filter.h"

#include <fmt/format.h>

#include <cmath>

#include "filters/filter_params.h"

namespace eyetrace {

// Members used by evaluate() are set before the sampler tabulates it.
MitchellFilter::MitchellFilter(Vec2 radius, float b, float c)
    : radius_(radius),
      b_(b),
      c_(c),
      sampler_(*this,
               IVec2(filter_sampling::filter_table_cells(radius.x), filter_sampling::filter_table_cells(radius.y)),
               radius.x * radius.y / 4.f) {}

float MitchellFilter::mitchell_1d(float x) const {
  x = std::abs(x);
  float b = b_, c = c_;
  if (x <= 1.f)
    return ((12.f - 9.f * b - 6.f * c) * x * x * x + (-18.f + 12.f * b + 6.f * c) * x * x + (6.f - 2.f * b)) *
           (1.f / 6.f);
  if (x <= 2.f)
    return ((-b - 6.f * c) * x * x * x + (6.f * b + 30.f * c) * x * x + (-12.f * b - 48.f * c) * x +
            (8.f * b + 24.f * c)) *
           (1.f / 6.f);
  return 0.f;
}

std::string MitchellFilter::to_string() const {
  return fmt::format("MitchellFilter[xradius={} yradius={} B={} C={}]", radius_.x, radius_.y, b_, c_);
}

const PluginSpec& mitchell_filter_spec() {
  static const PluginSpec spec{
      "PixelFilter", "the Mitchell-Netravali cubic", "—",
      filter_radius_params(2) +
          std::vector<ParamSpec>{param::real("B", 1.0 / 3.0).range(-10, 10).shown_default("1/3"),
                                 param::real("C", 1.0 / 3.0).range(-10, 10).shown_default("1/3")}};
  return spec;
}

std::unique_ptr<Filter> create_mitchell_filter(const ParameterList& list) {
  const PluginParams params(list, mitchell_filter_spec(), "mitchell");
  Vec2 radius = read_filter_radius(params);
  float b = params.get_float("B");
  float c = params.get_float("C");
  return std::make_unique<MitchellFilter>(radius, b, c);
}

}  // namespace eyetrace
