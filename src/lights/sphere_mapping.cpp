#include "lights/sphere_mapping.h"

#include <utility>

namespace eyetrace {

// The square [-1,1]^2 is folded like an octahedron: the inner diamond |u| + |v| < 1 is the
// upper hemisphere, the four outer triangles the lower one. Distance from the diamond's
// edge, r, sets z = 1 - r^2 (area preserving), the position along the edge sets phi.
Vec3 equal_area_square_to_sphere(Vec2 p) {
  float u = 2.f * p.x - 1.f, v = 2.f * p.y - 1.f;
  float up = std::abs(u), vp = std::abs(v);
  float signed_distance = 1.f - (up + vp);
  float r = 1.f - std::abs(signed_distance);
  float phi = (r == 0.f ? 1.f : (vp - up) / r + 1.f) * (kPi / 4.f);
  float z = std::copysign(1.f - r * r, signed_distance);
  float cos_phi = std::copysign(std::cos(phi), u);
  float sin_phi = std::copysign(std::sin(phi), v);
  float s = r * safe_sqrt(2.f - r * r);
  return Vec3(cos_phi * s, sin_phi * s, z);
}

// The exact inverse of the map above (pbrt-v4 uses a polynomial for atan; std::atan keeps
// sample -> direction -> pixel round trips in the same pixel).
Vec2 equal_area_sphere_to_square(const Vec3& d) {
  float x = std::abs(d.x), y = std::abs(d.y), z = std::abs(d.z);
  float r = safe_sqrt(1.f - z);
  float a = std::max(x, y), b = std::min(x, y);
  b = a == 0.f ? 0.f : b / a;
  float phi = std::atan(b) * (2.f / kPi);
  if (x < y) phi = 1.f - phi;
  float v = phi * r;
  float u = r - v;
  if (d.z < 0.f) {
    std::swap(u, v);
    u = 1.f - u;
    v = 1.f - v;
  }
  u = std::copysign(u, d.x);
  v = std::copysign(v, d.y);
  return Vec2(std::clamp(0.5f * (u + 1.f), 0.f, 1.f), std::clamp(0.5f * (v + 1.f), 0.f, 1.f));
}

Vec3 latlong_square_to_sphere(Vec2 p) {
  float phi = p.x * 2.f * kPi, theta = p.y * kPi;
  float sin_theta = std::sin(theta);
  return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta));
}

Vec2 latlong_sphere_to_square(const Vec3& d) {
  float phi = std::atan2(d.y, d.x);
  if (phi < 0.f) phi += 2.f * kPi;
  float theta = std::acos(std::clamp(d.z, -1.f, 1.f));
  return Vec2(std::clamp(phi * kInv2Pi, 0.f, 1.f), std::clamp(theta * kInvPi, 0.f, 1.f));
}

}  // namespace eyetrace
