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

}  // namespace eyetrace
