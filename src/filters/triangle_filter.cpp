#include "filters/triangle_filter.h"

#include <fmt/format.h>

#include "filters/filter_params.h"

namespace eyetrace {

// Half the mass on each side; within a side the CDF is quadratic, so the inverse is a sqrt.
float sample_tent(float u, float r) {
  if (u < 0.5f) {
    float v = 2.f * u;
    return std::max(-r, -r + r * std::sqrt(v));
  }
  float v = 2.f * u - 1.f;
  return std::min(r, r - r * std::sqrt(1.f - v));
}

FilterSample TriangleFilter::sample(Vec2 u) const {
  return FilterSample{Vec2(sample_tent(u.x, radius_.x), sample_tent(u.y, radius_.y)), 1.f};
}

std::string TriangleFilter::to_string() const {
  return fmt::format("TriangleFilter[xradius={} yradius={}]", radius_.x, radius_.y);
}

const PluginSpec& triangle_filter_spec() {
  static const PluginSpec spec{"PixelFilter", "weight falling linearly to zero at the radius", "—",
                               filter_radius_params(2)};
  return spec;
}

std::unique_ptr<Filter> create_triangle_filter(const ParameterList& list) {
  return std::make_unique<TriangleFilter>(read_filter_radius(PluginParams(list, triangle_filter_spec(), "triangle")));
}

}  // namespace eyetrace
