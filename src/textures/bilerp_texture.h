// pbrt-v4's "bilerp" texture: the bilinear interpolation of four values at the corners of the
// (s, t) unit square (v00 at (0, 0), v10 at (1, 0), v01 at (0, 1), v11 at (1, 1); defaults 0, 0,
// 1, 1), through any 2-D mapping (texture_mapping.h). Outside the square it extrapolates, as
// pbrt-v4's does.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& bilerp_texture_spec();
std::unique_ptr<FloatTexture> create_bilerp_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_bilerp_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
