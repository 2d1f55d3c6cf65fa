// pbrt-v4's "subsurface" material: a (rough) dielectric boundary over a homogeneous scattering
// medium whose transport is the photon beam diffusion BSSRDF (bssrdf_table.h,
// tabulated_bssrdf.h). The medium is given, as in pbrt-v4, by exactly one of: "name" (measured
// data, core/measured_media.h, with g = 0), "sigma_a" + "sigma_s", "reflectance" (+ "mfp",
// inverted through the table), or nothing (pbrt-v4's defaults); "scale" multiplies the
// coefficients (or the mean free path). Defaults: eta 1.33, g 0, roughness 0, remaproughness
// true.
#pragma once
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

std::unique_ptr<Material> create_subsurface_material(const MaterialContext& ctx);
const PluginSpec& subsurface_material_spec();

}  // namespace eyetrace
