// A ray in world space, the unit the renderer traces, and the spawning of new rays from
// surface points: origins are offset just past the point's floating-point error box so a
// spawned ray cannot re-hit the surface it leaves (pbrt-v4, PBR 4th ed. section 6.8.6).
#pragma once
#include "core/float_error.h"
#include "core/interaction.h"
#include "core/math.h"

namespace eyetrace {

struct Ray {
  Vec3 o{0.f};
  Vec3 d{0.f, 0.f, 1.f};
  float tmax = kInfinity;
  float time = 0.f;
  Vec3 at(float t) const { return o + t * d; }
};

// Fraction of a shadow ray's length left unexplored before its target (pbrt-v4's
// ShadowEpsilon); the target's own error box is already stepped over by offsetting it.
inline constexpr float kShadowEpsilon = 0.0001f;

// The true surface point lies inside the box p +- p_error. Moving p along the geometric
// normal n by d = dot(|n|, p_error) reaches the plane through the box corner farthest along n,
// so the new origin lies outside the box on the side w leaves towards, past the surface.
// Adding the offset rounds, so each coordinate is then stepped one float further away from p.
inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& p_error, const Vec3& n, const Vec3& w) {
  float d = glm::dot(glm::abs(n), p_error);
  Vec3 offset = d * n;
  if (glm::dot(w, n) < 0.f) offset = -offset;
  Vec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.f)
      po[i] = next_float_up(po[i]);
    else if (offset[i] < 0.f)
      po[i] = next_float_down(po[i]);
  }
  return po;
}

inline Ray spawn_ray(const Vec3& p, const Vec3& p_error, const Vec3& n, const Vec3& d, float time = 0.f) {
  return Ray{offset_ray_origin(p, p_error, n, d), d, kInfinity, time};
}

inline Ray spawn_ray(const SurfaceInteraction& si, const Vec3& d) {
  return spawn_ray(si.p, si.p_error, si.n, d, si.time);
}

// A ray from one surface point to another: both ends are offset off their surfaces (the
// target towards the origin), and tmax = 1 - kShadowEpsilon stops short of the target.
// A target with a zero normal (a point light, a far-away point) is not offset.
inline Ray spawn_ray_to(const Vec3& p_from, const Vec3& err_from, const Vec3& n_from, float time, const Vec3& p_to,
                        const Vec3& err_to, const Vec3& n_to) {
  Vec3 o = offset_ray_origin(p_from, err_from, n_from, p_to - p_from);
  Vec3 target = offset_ray_origin(p_to, err_to, n_to, o - p_to);
  return Ray{o, target - o, 1.f - kShadowEpsilon, time};
}

inline Ray spawn_ray_to(const SurfaceInteraction& si, const Vec3& p_to, const Vec3& err_to, const Vec3& n_to) {
  return spawn_ray_to(si.p, si.p_error, si.n, si.time, p_to, err_to, n_to);
}

}  // namespace eyetrace
