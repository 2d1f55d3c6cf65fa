#include "materials/bump_map.h"

#include <cmath>

namespace eyetrace {

SurfaceInteraction apply_bump_map(const FloatTexture* displacement, const SurfaceInteraction& si) {
  if (!displacement) return si;
  const TextureEvalContext at(si);
  TextureEvalContext shifted = at;
  shifted.p = si.p + kBumpStep * si.dpdu;
  shifted.uv = si.uv + Vec2(kBumpStep, 0.f);
  const float d_u = displacement->evaluate(shifted);
  shifted.p = si.p + kBumpStep * si.dpdv;
  shifted.uv = si.uv + Vec2(0.f, kBumpStep);
  const float d_v = displacement->evaluate(shifted);
  const float d = displacement->evaluate(at);
  const Vec3 dpdu = si.dpdu + (d_u - d) / kBumpStep * si.ns;
  const Vec3 dpdv = si.dpdv + (d_v - d) / kBumpStep * si.ns;
  Vec3 ns = glm::cross(dpdu, dpdv);
  const float len2 = glm::dot(ns, ns);
  // A texture that returns NaN or Inf, or a frame that collapses (dpdu parallel to dpdv after
  // displacement): keep the hit's own shading geometry rather than let a NaN normal through.
  if (!(len2 > 0.f) || !std::isfinite(len2) || !is_finite(dpdu) || !is_finite(dpdv)) return si;
  ns /= std::sqrt(len2);
  if (glm::dot(ns, si.n) < 0.f) ns = -ns;
  SurfaceInteraction out = si;
  out.ns = ns;
  out.dpdu = dpdu;
  out.dpdv = dpdv;
  return out;
}

}  // namespace eyetrace
