// Parameters every pbrt-v4 medium reads the same way: absorption and scattering coefficients
// (unbounded spectra, never negative) and the Henyey-Greenstein asymmetry g.
#pragma once
#include <string>

#include "core/spectrum.h"
#include "scene/param_spec.h"

namespace eyetrace {

// A coefficient per unit length: any non-negative spectrum (not bounded by 1); a negative or
// non-finite value is an error naming the parameter.
Spectrum coefficient_param(const PluginParams& p, const std::string& name);
// "g", checked to lie in (-1, 1), where the phase function exists.
float asymmetry_param(const PluginParams& p);
// "p0" and "p1", the box a grid or cloud fills in the medium's space; p1 must exceed p0.
Bounds3 medium_bounds_param(const PluginParams& p);

}  // namespace eyetrace
