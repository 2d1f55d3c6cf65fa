// pbrt-v4's "dielectric" material: "eta" (float or spectrum, used at 550 nm; default 1.5),
// "roughness" or "uroughness"/"vroughness" (default 0: smooth), "remaproughness" (true).
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

std::unique_ptr<Material> create_dielectric_material(const MaterialContext& ctx);

// The refractive index of a material's "eta" parameter at 550 nm (pbrt-v4 accepts a float
// or a spectrum); `def` when absent. Shared by dielectric and coateddiffuse.
// "eta" as a float or a spectrum read at 550 nm (shared with coateddiffuse).
ParamSpec eta_at_550_param();
float read_eta_at_550(const PluginParams& params);
const PluginSpec& dielectric_material_spec();

}  // namespace eyetrace
