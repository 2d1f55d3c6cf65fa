// pbrt-v4's "hair" material: the fibre BSDF of Chiang et al. 2016 (hair_bxdf.h) on any shape
// with (u, v): the fibre runs along dpdu and v goes across it, h = 2 v - 1, as on pbrt-v4's
// curves. The fibre's absorption is given as "sigma_a", or as the colour "reflectance" (pbrt-v4
// also reads it as "color"), or as "eumelanin" and "pheomelanin" concentrations, in that
// order of precedence (default: eumelanin 1.3, brown hair). Like pbrt-v4's, it has no bump or
// normal map.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& hair_material_spec();
std::unique_ptr<Material> create_hair_material(const MaterialContext& ctx);

}  // namespace eyetrace
