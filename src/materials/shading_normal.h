// How a material perturbs its hit's shading normal, as every pbrt-v4 material may: a
// "normalmap" image (normal_map.h) or a "texture displacement" bump map (bump_map.h). Given
// both, the normal map alone applies, as in pbrt-v4 (SurfaceInteraction::GetBSDF).
#pragma once
#include <vector>

#include "core/interaction.h"
#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

class ImageTexture;

struct ShadingNormal {
  const ImageTexture* normal_map = nullptr;
  const FloatTexture* displacement = nullptr;

  // "normalmap" and "displacement", for a material's parameter table.
  static std::vector<ParamSpec> declared();
  static ShadingNormal read(const MaterialContext& ctx, const PluginParams& params);
  SurfaceInteraction apply(const SurfaceInteraction& hit) const;
};

}  // namespace eyetrace
