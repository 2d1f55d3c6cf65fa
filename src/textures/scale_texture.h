// pbrt-v4's "scale" texture: "tex" (default 1) times "scale" (a float texture, default 1).
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& scale_texture_spec();
std::unique_ptr<FloatTexture> create_scale_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_scale_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
