// pbrt-v4's "thindielectric" material: a thin glass slab ("eta", float or spectrum, default
// 1.5; a spectrum that varies keeps only the hero wavelength, as pbrt-v4 does), rendered with
// ThinDielectricBxDF.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& thindielectric_material_spec();
std::unique_ptr<Material> create_thindielectric_material(const MaterialContext& ctx);

}  // namespace eyetrace
