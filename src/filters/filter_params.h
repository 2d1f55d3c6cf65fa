// The radius every pixel filter reads ("xradius", "yradius" in pixels, pbrt-v4's names),
// declared once here and added to each filter's table.
#pragma once
#include <vector>

#include "scene/param_spec.h"

namespace eyetrace {

// Below 1e-3 pixel a filter is no filter at all; beyond 64 pixels it blurs the image away.
inline std::vector<ParamSpec> filter_radius_params(double default_radius) {
  return {param::real("xradius", default_radius).range(1e-3, 64).with_unit("pixels"),
          param::real("yradius", default_radius).range(1e-3, 64).with_unit("pixels")};
}

inline Vec2 read_filter_radius(const PluginParams& params) {
  return Vec2(params.get_float("xradius"), params.get_float("yradius"));
}

}  // namespace eyetrace
