// pbrt-v4's "checkerboard" texture: "tex1" (default 1) on the squares whose integer
// coordinates sum to an even number, "tex2" (default 0) on the others. "dimension" 2 uses
// the 2D mapping parameters (see texture_mapping.h); 3 makes a solid checker in texture
// space. 2D lookups with a footprint are box-free antialiased: the square wave is
// integrated in closed form against a triangle filter.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

// Weight of tex2 in [0, 1] at (s, t), averaged over a triangle filter of half-width r.
float checkerboard_2d(Vec2 st, float r);
float checkerboard_3d(const Vec3& p);

const PluginSpec& checkerboard_texture_spec();
std::unique_ptr<FloatTexture> create_checkerboard_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_checkerboard_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
