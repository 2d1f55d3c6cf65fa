// pbrt-v4's "dielectric" material: "eta" (float, or a spectrum that makes it disperse; 1.5),
// "roughness" or "uroughness"/"vroughness" (default 0: smooth), "remaproughness" (true).
#pragma once
#include <memory>

#include "core/material.h"
#include "core/spectrum.h"
#include "scene/registry.h"

namespace eyetrace {

std::unique_ptr<Material> create_dielectric_material(const MaterialContext& ctx);

// "eta" as a float or a spectrum read at 550 nm (coateddiffuse's coat, whose closed-form
// constants are computed once; the dielectric itself uses the whole spectrum).
ParamSpec eta_at_550_param();
float read_eta_at_550(const PluginParams& params, const std::string& name = "eta");

// "eta" read whole: a constant, or a spectrum (a named glass, a tabulated one), which makes the
// material dispersive; every value in 360-830 nm is checked to be positive and finite.
struct DielectricEta {
  Spectrum spectrum;
  bool dispersive = false;
};
DielectricEta read_dielectric_eta(const MaterialContext& ctx, const PluginParams& params,
                                  const std::string& name = "eta");
const PluginSpec& dielectric_material_spec();

}  // namespace eyetrace
