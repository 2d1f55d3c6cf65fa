// The roughness parameters pbrt-v4 materials share: "roughness" or the anisotropic pair
// "uroughness"/"vroughness" (each a float or a float texture), and "remaproughness".
#pragma once
#include "core/texture.h"
#include "materials/microfacet.h"
#include "scene/registry.h"

namespace eyetrace {

struct RoughnessParams {
  const FloatTexture* u = nullptr;
  const FloatTexture* v = nullptr;
  bool remap = true;

  // "roughness", "uroughness", "vroughness", "remaproughness": every rough material's table has them.
  // A layered material names each layer's with a prefix ("interface.", "conductor.") and
  // declares the one "remaproughness" apart (with_remap false).
  static std::vector<ParamSpec> declared(const std::string& prefix = "", bool with_remap = true);
  static RoughnessParams read(const MaterialContext& ctx, const PluginParams& params, const std::string& prefix = "");
  // The distribution at a hit; negative roughness values count as 0.
  TrowbridgeReitz distribution(const TextureEvalContext& tc) const;
};

}  // namespace eyetrace
