// pbrt-v4's "constant" texture plugin ("value", default 1); the texture classes themselves are
// in core/texture.h, since plain material parameters become them too.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& constant_texture_spec();
std::unique_ptr<FloatTexture> create_constant_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_constant_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
