// Warps from the unit square to the domains the renderer samples, with their densities.
// Each is checked by a chi-square test in tests/core/sampling_test.cpp.
#pragma once
#include "core/math.h"

namespace eyetrace {

// Shirley-Chiu concentric map: uniform on the unit disk, low distortion (keeps strata).
inline Vec2 sample_uniform_disk_concentric(Vec2 u) {
  Vec2 o = 2.f * u - Vec2(1.f);
  if (o.x == 0.f && o.y == 0.f) return Vec2(0.f);
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = (kPi / 4.f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = kPi / 2.f - (kPi / 4.f) * (o.x / o.y);
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}

inline Vec2 sample_uniform_disk_polar(Vec2 u) {
  float r = std::sqrt(u.x), theta = 2.f * kPi * u.y;
  return Vec2(r * std::cos(theta), r * std::sin(theta));
}

// Cosine-weighted hemisphere about +z (Malley's method); pdf = cos(theta) / pi.
inline Vec3 sample_cosine_hemisphere(Vec2 u) {
  Vec2 d = sample_uniform_disk_concentric(u);
  float z = safe_sqrt(1.f - d.x * d.x - d.y * d.y);
  return Vec3(d.x, d.y, z);
}
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta * kInvPi; }

inline Vec3 sample_uniform_sphere(Vec2 u) {
  float z = 1.f - 2.f * u.x;
  float r = safe_sqrt(1.f - z * z);
  float phi = 2.f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
inline float uniform_sphere_pdf() { return 1.f / (4.f * kPi); }

inline Vec3 sample_uniform_hemisphere(Vec2 u) {
  float z = u.x;
  float r = safe_sqrt(1.f - z * z);
  float phi = 2.f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
inline float uniform_hemisphere_pdf() { return kInv2Pi; }

// Uniform in the cone of directions within acos(cos_max) of +z.
inline Vec3 sample_uniform_cone(Vec2 u, float cos_max) {
  float cos_t = (1.f - u.x) + u.x * cos_max;
  float sin_t = safe_sqrt(1.f - cos_t * cos_t);
  float phi = u.y * 2.f * kPi;
  return Vec3(std::cos(phi) * sin_t, std::sin(phi) * sin_t, cos_t);
}
inline float uniform_cone_pdf(float cos_max) { return 1.f / (2.f * kPi * (1.f - cos_max)); }

// Uniform barycentrics on a triangle (Heitz 2019, low distortion); returns (b0, b1).
inline Vec2 sample_uniform_triangle(Vec2 u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2.f;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2.f;
    b0 = u.x - b1;
  }
  return Vec2(b0, b1);
}

// Multiple importance sampling: the power heuristic with beta = 2.
inline float power_heuristic(float f_pdf, float g_pdf) {
  float f = f_pdf * f_pdf, g = g_pdf * g_pdf;
  if (std::isinf(f)) return 1.f;
  return f + g > 0.f ? f / (f + g) : 0.f;
}

}  // namespace eyetrace
