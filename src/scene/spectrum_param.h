// Spectrum-valued scene parameters: a "spectrum" (constant, [lambda value ...] pairs or a
// named spectrum) or "blackbody" temperature to the renderer's RGB, and a "float",
// "rgb" or "spectrum" parameter's value at one wavelength. Errors name the parameter.
#pragma once
#include "core/math.h"
#include "scene/params.h"

namespace eyetrace {

RGB spectrum_param_to_rgb(const Param& p);
// A refractive index at 550 nm, say; "rgb" gives its green channel.
float spectrum_param_at(const Param& p, float lambda_nm);

}  // namespace eyetrace
