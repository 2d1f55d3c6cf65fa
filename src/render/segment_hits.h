// Every surface a segment crosses, nearest first: the "intersect all" a BSSRDF probe needs
// (pbrt-v4's VolPathIntegrator loop), built on Scene::intersect so the scene itself is
// unchanged. Each next ray starts past the last hit (offset by its error bound, core/ray.h);
// the target is a free point, not offset.
#pragma once
#include "core/ray.h"
#include "render/scene.h"

namespace eyetrace {

// Calls visit(si) for each hit on p0 -> p1 and returns how many rays were traced. At most
// `max_hits` hits are visited: a probe crossing more surfaces than that (a degenerate stack of
// coincident shapes) stops there rather than loop.
template <typename Visit>
int for_each_hit_on_segment(const Scene& scene, const Vec3& p0, const Vec3& p1, float time, Visit&& visit,
                            int max_hits = 64) {
  Ray ray{p0, p1 - p0, 1.f, time};
  int rays = 0;
  for (int hits = 0; hits < max_hits; ++hits) {
    if (ray.d == Vec3(0.f)) break;
    SurfaceInteraction si;
    ++rays;
    if (!scene.intersect(ray, &si)) break;
    visit(si);
    ray = spawn_ray_to(si.p, si.p_error, si.n, time, p1, Vec3(0.f), Vec3(0.f));
  }
  return rays;
}

}  // namespace eyetrace
