// The radius every pixel filter reads ("xradius", "yradius" in pixels, pbrt-v4's names).
#pragma once
#include <fmt/format.h>

#include "scene/params.h"

namespace eyetrace {

inline Vec2 read_filter_radius(const ParameterList& params, float default_radius) {
  // Below 1e-3 pixel a filter is no filter at all; beyond 64 pixels it blurs the image away.
  auto read = [&](const char* name) {
    float v = params.get_float(name, default_radius);
    if (!(v >= 1e-3f && v <= 64.f)) params.fail(name, fmt::format("value {} is outside [0.001, 64] pixels", v));
    return v;
  };
  float rx = read("xradius");
  return Vec2(rx, read("yradius"));
}

}  // namespace eyetrace
