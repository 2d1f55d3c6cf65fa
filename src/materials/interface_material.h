// pbrt-v4's "interface" material: a surface that only bounds a participating medium. Its
// bsdf() is null, which tells the integrator to continue the ray unchanged.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& interface_material_spec();
std::unique_ptr<Material> create_interface_material(const MaterialContext& ctx);

}  // namespace eyetrace
