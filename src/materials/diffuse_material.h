// pbrt-v4's "diffuse" material: Lambertian reflection with "reflectance" (default 0.5).
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& diffuse_material_spec();
std::unique_ptr<Material> create_diffuse_material(const MaterialContext& ctx);

}  // namespace eyetrace
