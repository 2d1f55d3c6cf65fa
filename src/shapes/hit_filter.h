// Embree filter functions of the shapes that may turn a candidate hit down (alpha cut-outs, a
// ribbon's narrowed band): Embree calls them for every candidate hit of their geometry with N
// rays (N = 1 for rtcIntersect1 / rtcOccluded1, but written for any N); clearing valid[i]
// makes Embree ignore that hit and look on. The ray is in the space the geometry lives in
// (instance space for an instanced one), its tfar the candidate's distance.
#pragma once
#include <embree3/rtcore.h>

#include "core/math.h"

namespace eyetrace {

// Keeps the candidates for which accepts(prim_id, u, v, origin, direction, t) is true.
template <typename Accepts>
void filter_hits(const RTCFilterFunctionNArguments* args, Accepts&& accepts) {
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] == 0) continue;
    const Vec3 o(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i), RTCRayN_org_z(args->ray, n, i));
    const Vec3 d(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i), RTCRayN_dir_z(args->ray, n, i));
    if (!accepts(RTCHitN_primID(args->hit, n, i), RTCHitN_u(args->hit, n, i), RTCHitN_v(args->hit, n, i), o, d,
                 RTCRayN_tfar(args->ray, n, i)))
      args->valid[i] = 0;
  }
}

}  // namespace eyetrace
