// pbrt-v4's "measured" material: an RGL measured BRDF read from a tensor (.bsdf) file
// ("string filename", required; measured_brdf.h), evaluated and sampled by MeasuredBxDF, with
// the "displacement" and "normalmap" every pbrt-v4 material has. A file is read once however
// many materials name it.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& measured_material_spec();
std::unique_ptr<Material> create_measured_material(const MaterialContext& ctx);

}  // namespace eyetrace
