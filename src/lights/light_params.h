// Parameter conventions every light shares (pbrt-v4 semantics in an RGB renderer): an
// emission spectrum defaulting to white, a non-negative "scale", and the photometric
// normalisations "power" / "illuminance", which rescale the emission so that the luminance
// of the emitted quantity equals the value given, "scale" then multiplying on top (pbrt-v4:
// a scene with "scale" 2 and "power" 100 emits 200).
#pragma once
#include <optional>
#include <string>

#include "scene/params.h"

namespace eyetrace {

// An "rgb"/"spectrum"/"blackbody" emission parameter; white (the colour space's illuminant,
// as pbrt-v4 defaults) when absent. Negative components are errors naming the parameter.
RGB emission_param(const ParameterList& params, const std::string& name);
// The same, nullopt when absent (for lights where "L" competes with an image).
std::optional<RGB> emission_param_or_null(const ParameterList& params, const std::string& name);
// "scale", default 1, must be finite and >= 0.
float scale_param(const ParameterList& params);
// A photometric target ("power", "illuminance"): nullopt when absent, an error unless > 0.
std::optional<float> positive_param(const ParameterList& params, const std::string& name);
// The factor that makes `emitted_luminance` (> 0) equal `target`; 1 when there is no
// target, or when nothing is emitted (a black light cannot be normalised: stays black).
float photometric_factor(std::optional<float> target, float emitted_luminance);

// Mean of the channels: the scalar "power" the light sampler weighs lights by (pbrt-v4
// averages Phi over the sampled wavelengths; a blue light still gets shadow rays).
inline float channel_mean(const RGB& c) { return (c.r + c.g + c.b) / 3.f; }

}  // namespace eyetrace
