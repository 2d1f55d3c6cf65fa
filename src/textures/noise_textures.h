// pbrt-v4's solid noise textures (float only, in the texture's coordinate system):
//   "fbm":      fbm(p, roughness, octaves)              ("octaves" 8, "roughness" 0.5)
//   "wrinkled": turbulence(p, roughness, octaves)       (the same parameters)
//   "windy":    |fbm(0.1 p, 0.5, 3)| fbm(p, 0.5, 6)     (wind strength times wave height)
// with perlin_noise.h's sums (every octave: see there for the one difference from pbrt-v4).
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& fbm_texture_spec();
const PluginSpec& wrinkled_texture_spec();
const PluginSpec& windy_texture_spec();
std::unique_ptr<FloatTexture> create_fbm_texture(const TextureContext& ctx);
std::unique_ptr<FloatTexture> create_wrinkled_texture(const TextureContext& ctx);
std::unique_ptr<FloatTexture> create_windy_texture(const TextureContext& ctx);

}  // namespace eyetrace
