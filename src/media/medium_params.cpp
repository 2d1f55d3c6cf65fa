#include "media/medium_params.h"

#include <cmath>

namespace eyetrace {

Spectrum coefficient_param(const PluginParams& p, const std::string& name) {
  const SpectrumValue v = p.get_spectrum(name, SpectrumType::Unbounded);
  if (v.rgb && (v.rgb->r < 0.f || v.rgb->g < 0.f || v.rgb->b < 0.f))
    p.fail(name, fmt::format("({}, {}, {}) has a negative component: a medium cannot add what it removes", v.rgb->r,
                             v.rgb->g, v.rgb->b));
  const Spectrum s = v.as(SpectrumType::Unbounded);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.f)
    if (!(s(l) >= 0.f) || !std::isfinite(s(l))) p.fail(name, fmt::format("is negative or not finite at {} nm", l));
  return s;
}

float asymmetry_param(const PluginParams& p) {
  const float g = p.get_float("g");
  if (!(std::abs(g) < 1.f)) p.fail("g", fmt::format("{} is outside (-1, 1): the phase function would not exist", g));
  return g;
}

Bounds3 medium_bounds_param(const PluginParams& p) {
  Bounds3 b;
  b.lo = p.get_point3("p0");
  b.hi = p.get_point3("p1");
  for (int i = 0; i < 3; ++i)
    if (!(b.hi[i] > b.lo[i]) || !std::isfinite(b.hi[i] - b.lo[i]))
      p.fail("p1", fmt::format("({}, {}, {}) must exceed p0 ({}, {}, {}) in every coordinate: the box would be empty",
                               b.hi.x, b.hi.y, b.hi.z, b.lo.x, b.lo.y, b.lo.z));
  return b;
}

}  // namespace eyetrace
