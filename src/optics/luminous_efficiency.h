// The photopic luminous efficiency function V(lambda) of the CIE 1924 standard photopic observer,
// which is the CIE 1931 2-degree colour-matching function y-bar: how much a watt of each
// wavelength contributes to luminance (1 at 555 nm). It weights the wavelengths of the
// polychromatic PSF and MTF (polychromatic_psf.h). The optics library keeps its own copy (it
// never includes src/core, whose cie_tables.h holds the same column).
#pragma once

namespace eyetrace::optics {

// Tabulated every 5 nm from 380 to 780 nm.
inline constexpr double kPhotopicMin_nm = 380.0, kPhotopicMax_nm = 780.0, kPhotopicStep_nm = 5.0;

// V(lambda), linearly interpolated between the 5 nm rows; 0 outside [380, 780] nm and for NaN.
double photopic_luminous_efficiency(double wavelength_nm);

}  // namespace eyetrace::optics
