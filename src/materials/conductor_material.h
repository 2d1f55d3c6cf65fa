// pbrt-v4's "conductor" material: complex index "eta" + i "k" (spectrum textures, default
// copper: "metal-Cu-eta"/"metal-Cu-k") or, instead, a normal-incidence "reflectance";
// "roughness" or "uroughness"/"vroughness" (default 0), "remaproughness" (true).
#pragma once
#include <memory>

#include "core/material.h"
#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& conductor_material_spec();
std::unique_ptr<Material> create_conductor_material(const MaterialContext& ctx);

// A metal's complex index as pbrt-v4's conductors read it: PREFIX"eta" and PREFIX"k" (default
// copper) or, instead, "reflectance" (then eta = 1 and the k whose normal reflectance it is).
// Shared by "conductor" and the base of "coatedconductor" (prefix "conductor.").
struct ConductorIndex {
  const SpectrumTexture* eta = nullptr;
  const SpectrumTexture* k = nullptr;
  const SpectrumTexture* reflectance = nullptr;

  static std::vector<ParamSpec> declared(const std::string& prefix = "");
  static ConductorIndex read(const MaterialContext& ctx, const PluginParams& params, const std::string& prefix = "");
  // eta and k at the sample's wavelengths; a negative value counts as 0, a non-finite eta as 1.
  void evaluate(TextureEvalContext tc, const SampledWavelengths& lambda, SampledSpectrum* eta,
                SampledSpectrum* k) const;
};

}  // namespace eyetrace
