// pbrt-v4's "mix" texture: (1 - amount) tex1 + amount tex2, with "tex1" (default 0),
// "tex2" (default 1) and "amount" (a float texture, default 0.5).
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& mix_texture_spec();
std::unique_ptr<FloatTexture> create_mix_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_mix_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
