// pbrt-v4's "directionmix" texture: tex1 where the surface faces `dir`, tex2 where it is edge-on
// to it: amount = |n . dir| (n the geometric normal, dir in the texture's coordinate system,
// default (0, 1, 0)), value = amount tex1 + (1 - amount) tex2 (tex1 default 0, tex2 default 1).
// Exporters use it for moss on the tops of things.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& directionmix_texture_spec();
std::unique_ptr<FloatTexture> create_directionmix_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_directionmix_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
