// pbrt-v4's "coatedconductor" material: a metal ("conductor.eta"/"conductor.k", default copper,
// or "reflectance"; "conductor.roughness" or "conductor.uroughness"/"conductor.vroughness", 0)
// under a dielectric coat ("interface.eta" 1.5, a spectrum keeps the hero wavelength;
// "interface.roughness" or "interface.uroughness"/"interface.vroughness", 0; "thickness" 0.01
// and "albedo" 0 of its medium), "remaproughness" true; rendered with coated_conductor_bxdf.h.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& coatedconductor_material_spec();
std::unique_ptr<Material> create_coatedconductor_material(const MaterialContext& ctx);

}  // namespace eyetrace
