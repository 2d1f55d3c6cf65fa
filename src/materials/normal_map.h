// pbrt-v4's "normalmap" material parameter: an RGB image (linear encoding, repeat wrap,
// t = 1 - v) whose texel c gives the shading normal 2c - 1 in the tangent frame
// (dpdu, ns x dpdu, ns) of the hit. Shared by every material that takes it.
#pragma once
#include "core/interaction.h"
#include "core/texture.h"
#include "scene/registry.h"
#include "textures/imagemap_texture.h"

namespace eyetrace {

// The image as a texture owned by ctx.textures, or null when the material has no
// "normalmap". A missing file is an error naming "normalmap" and the path.
ParamSpec normal_map_param();
const ImageTexture* read_normal_map(const MaterialContext& ctx, const PluginParams& params);

// The hit with its shading normal (and tangent) replaced; unchanged if `map` is null.
SurfaceInteraction apply_normal_map(const ImageTexture* map, const SurfaceInteraction& si);

}  // namespace eyetrace
