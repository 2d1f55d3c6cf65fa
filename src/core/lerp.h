// Linear interpolation of vectors (points, RGB colours: both are Vec3).
#pragma once

#include "core/math.h"

namespace eyetrace {

// a at t = 0, b at t = 1.
inline Vec3 lerp(float t, const Vec3& a, const Vec3& b) { return (1.f - t) * a + t * b; }

}  // namespace eyetrace
