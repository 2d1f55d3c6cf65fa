// pbrt-v4's bump mapping ("texture displacement" on a material): the surface is taken as
// displaced along its shading normal by the float texture d, p' = p + d(u, v) ns, and the
// shading normal becomes that displaced surface's, ns' ~ dp'/du x dp'/dv with
//   dp'/du = dpdu + (d(u + du, v) - d(u, v)) / du ns   (and likewise in v),
// the derivatives taken by finite differences as pbrt-v4's BumpMap does. Two differences from
// pbrt-v4, both documented in docs/scene-format.md: the step is always pbrt-v4's fallback
// du = dv = 0.0005 (eyetrace's hits carry no uv ray differentials, from which pbrt-v4 takes
// half a pixel's footprint), and the term d dn/du (the normal's own change, nonzero on curved
// surfaces with a nonzero displacement) is left out (the hits carry no dn/du).
#pragma once
#include "core/interaction.h"
#include "core/texture.h"

namespace eyetrace {

// pbrt-v4's fallback step in u and v.
inline constexpr float kBumpStep = 0.0005f;

// The hit with its shading normal and dpdu, dpdv replaced by the displaced surface's; the
// normal is turned to the geometric normal's side (pbrt-v4's SetShadingGeometry with the
// geometry authoritative). Unchanged if `displacement` is null or the displaced frame is
// degenerate or not finite.
SurfaceInteraction apply_bump_map(const FloatTexture* displacement, const SurfaceInteraction& si);

}  // namespace eyetrace
