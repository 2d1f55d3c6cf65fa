// pbrt-v4's "coateddiffuse" material: a diffuse base ("reflectance", 0.5) under a dielectric
// coat ("eta" 1.5, "roughness"/"uroughness"/"vroughness" 0, "remaproughness" true) of
// "thickness" 0.01 filled with a medium of "albedo" 0 and "g" 0. "maxdepth" (10) and
// "nsamples" (1) are accepted for compatibility. The model is closed-form, not pbrt-v4's
// random walk: see materials/coated_diffuse_bxdf.h.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& coateddiffuse_material_spec();
std::unique_ptr<Material> create_coateddiffuse_material(const MaterialContext& ctx);

}  // namespace eyetrace
