// The 24 reflectances of the Macbeth ColorChecker that pbrt-v4 fits a camera sensor's XYZ matrix
// to (PixelSensor::swatchReflectances, src/pbrt/film.cpp; Danny Pascale's BabelColor
// measurements, www.babelcolor.com, "ColorChecker RGB and spectra", used by pbrt-v4 by permission).
#pragma once

namespace eyetrace {

inline constexpr int kSwatchCount = 24;

// Reflectance of swatch i (0..23, the chart's reading order: dark skin, light skin, blue sky,
// ..., white 9.5, ..., black 2) at lambda: piecewise linear through the measurements every
// 10 nm from 380 to 730 nm, 0 outside them (as pbrt-v4's PiecewiseLinearSpectrum).
double swatch_reflectance(int i, double lambda_nm);

}  // namespace eyetrace
