// pbrt-v4's "diffusetransmission" material: Lambertian reflection ("reflectance", default 0.25)
// and Lambertian transmission ("transmittance", default 0.25), both times "scale" (default 1)
// and clamped to [0, 1], as pbrt-v4's DiffuseTransmissionMaterial (leaves, paper, lamp shades).
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& diffusetransmission_material_spec();
std::unique_ptr<Material> create_diffusetransmission_material(const MaterialContext& ctx);

}  // namespace eyetrace
