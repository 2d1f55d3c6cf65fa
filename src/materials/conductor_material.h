// pbrt-v4's "conductor" material: complex index "eta" + i "k" (spectrum textures, default
// copper: "metal-Cu-eta"/"metal-Cu-k") or, instead, a normal-incidence "reflectance";
// "roughness" or "uroughness"/"vroughness" (default 0), "remaproughness" (true).
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& conductor_material_spec();
std::unique_ptr<Material> create_conductor_material(const MaterialContext& ctx);

}  // namespace eyetrace
