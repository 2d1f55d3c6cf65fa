// pbrt-v4's "dots" texture: polka dots on the (s, t) plane (any 2-D mapping). Each unit cell
// around an integer point holds a dot of radius 0.35 where Perlin noise at the cell is positive,
// its centre shifted by noise by up to 0.15; "inside" (default 1) in a dot, "outside" (default 0)
// elsewhere, as pbrt-v4's InsidePolkaDot.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& dots_texture_spec();
std::unique_ptr<FloatTexture> create_dots_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_dots_spectrum_texture(const TextureContext& ctx);
// Whether (s, t) lies in a dot.
bool inside_polka_dot(Vec2 st);

}  // namespace eyetrace
