// pbrt-v4's "marble" texture (spectrum only): veins from a sine of the texture-space height
// perturbed by fbm, p scaled by "scale" (1): t = 1/2 + 1/2 sin(p.y + variation fbm(p, roughness,
// octaves)) ("variation" 0.2, "roughness" 0.5, "octaves" 8), coloured by pbrt-v4's cubic Bezier
// spline through its nine greys and blue-greys, times 1.5, as an sRGB reflectance.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& marble_texture_spec();
std::unique_ptr<SpectrumTexture> create_marble_spectrum_texture(const TextureContext& ctx);
// The RGB reflectance at spline parameter t in [0, 1].
RGB marble_colour(float t);

}  // namespace eyetrace
