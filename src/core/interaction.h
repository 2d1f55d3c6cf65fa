// A ray-surface hit turned into everything shading needs.
#pragma once
#include "core/math.h"

namespace eyetrace {

class Material;
class Light;
struct MediumInterface;

struct SurfaceInteraction {
  Vec3 p{0.f};
  // Conservative absolute rounding-error bound of p per axis (world space): the exact surface
  // point lies in p +- p_error. Each shape computes it; spawned rays step over it (core/ray.h).
  Vec3 p_error{0.f};
  Vec3 n{0.f, 0.f, 1.f};   // geometric normal, unit, flipped by ReverseOrientation/handedness
  Vec3 ns{0.f, 0.f, 1.f};  // shading normal (interpolated), same hemisphere as n
  Vec2 uv{0.f};
  Vec3 dpdu{1.f, 0.f, 0.f}, dpdv{0.f, 1.f, 0.f};
  Vec3 wo{0.f};  // unit, towards where the ray came from
  float t = 0.f;
  float time = 0.f;
  const Material* material = nullptr;  // null: an interface that only bounds a medium; pass through
  const Light* area_light = nullptr;   // the emitter on this surface, or null
  // The media on its two sides where the surface bounds a medium (inside != outside); null
  // where it does not, and a ray crossing it stays in the medium it was in (pbrt-v4).
  const MediumInterface* medium_interface = nullptr;
  // Screen-space footprint for texture filtering (0 = point sampling).
  float footprint = 0.f;
};

}  // namespace eyetrace
