// Vector types and small numeric helpers shared by the renderer (float) side.
// The optics library uses double (glm::dvec3) and converts once where a ray leaves the eye.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

#include "core/constants.h"

namespace eyetrace {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using IVec2 = glm::ivec2;
using Mat4 = glm::mat4;

// The renderer is RGB (linear Rec.709 primaries); spectral sampling can come later through
// CameraSample::wavelength_u without changing interfaces.
using RGB = glm::vec3;

inline float radians(float deg) { return deg * (kPi / 180.f); }
inline float luminance(const RGB& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline bool is_finite(const RGB& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }
inline bool is_black(const RGB& c) { return c.r == 0.f && c.g == 0.f && c.b == 0.f; }
inline float max_component(const RGB& c) { return std::max(c.r, std::max(c.g, c.b)); }
inline float safe_sqrt(float x) { return std::sqrt(std::max(0.f, x)); }
inline float sqr(float x) { return x * x; }

// Orthonormal basis around a unit vector (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
inline void coordinate_system(const Vec3& n, Vec3* s, Vec3* t) {
  float sign = std::copysign(1.f, n.z);
  float a = -1.f / (sign + n.z);
  float b = n.x * n.y * a;
  *s = Vec3(1.f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  *t = Vec3(b, sign + n.y * n.y * a, -n.y);
}

// A shading frame: local z is the normal.
struct Frame {
  Vec3 s, t, n;
  Frame() = default;
  explicit Frame(const Vec3& normal) : n(normal) { coordinate_system(n, &s, &t); }
  Vec3 to_local(const Vec3& v) const { return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)); }
  Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

struct Bounds3 {
  Vec3 lo{kInfinity}, hi{-kInfinity};
  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Bounds3& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return 0.5f * (lo + hi); }
  float radius() const { return empty() ? 0.f : 0.5f * glm::length(hi - lo); }
};

}  // namespace eyetrace
