// A ray in world space, the unit the renderer traces.
#pragma once
#include "core/math.h"

namespace eyetrace {

struct Ray {
  Vec3 o{0.f};
  Vec3 d{0.f, 0.f, 1.f};
  float tmax = kInfinity;
  float time = 0.f;
  Vec3 at(float t) const { return o + t * d; }
};

// Offset a ray origin off a surface along the geometric normal, away from the side the new
// direction leaves towards. Embree works in single precision, so the offset scales with the
// magnitude of the hit point (relative error of float arithmetic) plus a small absolute floor.
inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& n, const Vec3& w) {
  float mag = std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z)));
  float eps = 1e-4f * std::max(1.f, mag) * 0.05f + 1e-6f;
  Vec3 off = n * eps;
  return glm::dot(w, n) < 0.f ? p - off : p + off;
}

inline Ray spawn_ray(const Vec3& p, const Vec3& n, const Vec3& d, float time = 0.f) {
  return Ray{offset_ray_origin(p, n, d), d, kInfinity, time};
}

// A ray towards a point: tmax stops just short of the target so the target's own surface is
// not reported as an occluder.
inline Ray spawn_ray_to(const Vec3& p, const Vec3& n, const Vec3& target, float time = 0.f) {
  Vec3 o = offset_ray_origin(p, n, target - p);
  Vec3 d = target - o;
  return Ray{o, d, 1.f - 1e-4f, time};
}

}  // namespace eyetrace
