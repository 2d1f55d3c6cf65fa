#include "filters/box_filter.h"

#include <fmt/format.h>

#include "filters/filter_params.h"

namespace eyetrace {

FilterSample BoxFilter::sample(Vec2 u) const {
  Vec2 p((2.f * u.x - 1.f) * radius_.x, (2.f * u.y - 1.f) * radius_.y);
  return FilterSample{glm::clamp(p, -radius_, radius_), 1.f};
}

std::string BoxFilter::to_string() const {
  return fmt::format("BoxFilter[xradius={} yradius={}]", radius_.x, radius_.y);
}

const PluginSpec& box_filter_spec() {
  static const PluginSpec spec{"PixelFilter", "equal weight over the radius", "—", filter_radius_params(0.5)};
  return spec;
}

std::unique_ptr<Filter> create_box_filter(const ParameterList& list) {
  return std::make_unique<BoxFilter>(read_filter_radius(PluginParams(list, box_filter_spec(), "box")));
}

}  // namespace eyetrace
