// Spectrum-valued scene parameters: "rgb" values, "spectrum" constants, [lambda value] pairs
// and named spectra, "blackbody" temperatures, checked (errors name the parameter) and kept
// as given until a plugin says what it uses them as (core/spectrum.h: SpectrumType).
#pragma once
#include <optional>

#include "core/spectrum.h"
#include "scene/params.h"

namespace eyetrace {

// `type` matters only to spectra given as such: an Illuminant is normalised to luminance 1.
SpectrumValue spectrum_param_value(const Param& p, SpectrumType type);
// A refractive index at 550 nm, say; "rgb" gives its green channel.
float spectrum_param_at(const Param& p, float lambda_nm);
// An RGB read as a reflectance (SpectrumType::Albedo) is clamped to [0, 1] when it becomes a
// spectrum (core/spectrum.h); a component outside that range is no reflectance at all, so the
// clamp is announced: a warning naming the file, line, column and parameter (an error with
// --strict). pbrt-v4 stops with an error there instead.
void warn_if_not_reflectance(const Param& p, const RGB& rgb);
// A spectrum parameter given as numbers (not a texture) must be positive, or non-negative when
// zero_allowed, everywhere over the sampled range (RGB: every channel): an error naming the
// parameter and its smallest value otherwise. Textures are clamped where they are evaluated,
// as in pbrt-v4; a negative number written in the file is a mistake, not a clamp.
void check_constant_spectrum_sign(const ParameterList& params, const std::string& name, bool zero_allowed);

}  // namespace eyetrace
