// Where a grid or procedural medium sits: a box [p0, p1] in the medium's own space, placed in
// the scene by the transform current at its MakeNamedMedium (render_from_medium). Points are
// taken into the medium's space by the inverse; a ray's o and d are both transformed, so its
// parameter t is the same in both spaces and majorant segments need no conversion.
#pragma once
#include <optional>
#include <utility>

#include "core/majorant.h"
#include "core/ray.h"
#include "core/transform.h"

namespace eyetrace {

struct MediumBox {
  Bounds3 bounds;                // in the medium's space
  Transform medium_from_render;  // inverse of the CTM at MakeNamedMedium

  Vec3 to_medium(const Vec3& p_render) const { return medium_from_render.point(p_render); }
  // p (medium space) as a fraction of the box: the unit cube's coordinates grids are looked up at.
  Vec3 to_unit(const Vec3& p_medium) const { return (p_medium - bounds.lo) / (bounds.hi - bounds.lo); }

  // The ray in medium space and the part [t0, t1] of [0, t_max] inside the box.
  struct Clipped {
    Vec3 o, d;
    float t0, t1;
  };
  std::optional<Clipped> clip(const Ray& ray, float t_max) const {
    const Vec3 o = medium_from_render.point(ray.o), d = medium_from_render.vector(ray.d);
    const auto range = intersect_box(bounds, o, d, t_max);
    if (!range) return std::nullopt;
    return Clipped{o, d, range->first, range->second};
  }
};

}  // namespace eyetrace
