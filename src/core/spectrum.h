// Spectra turned into the renderer's RGB (linear sRGB: Rec.709 primaries, D65 white).
// The renderer is RGB, so every spectral parameter becomes one colour when the scene is
// built; scene parameters come in through scene/spectrum_param.h.
//
// Two conversions, because a spectrum means different things:
//  - reflectance-like (reflectances, conductor eta and k, [lambda value] pairs): the colour
//    of the spectrum seen under the colour space's white (D65), normalised per channel so
//    that any constant spectrum c gives exactly (c, c, c);
//  - emission (blackbody, stdillum-*): the XYZ of the spectrum itself, normalised to
//    luminance Y = 1. pbrt-v4 divides every light's spectrum by its photometric value, so a
//    blackbody emitter renders at 1 nit times "scale"; returning luminance 1 here gives that
//    result whether or not the light also normalises.
#pragma once
#include <array>
#include <span>

#include "core/cie_tables.h"
#include "core/math.h"
#include "core/named_spectra.h"

namespace eyetrace {

// A spectrum sampled at the CIE table's wavelengths (380..780 nm every 5 nm).
using SpectrumSamples = std::array<float, kCieRows>;

// Piecewise-linear spectrum through (lambda, value) points, held constant beyond its ends
// (as pbrt-v3 did; pbrt-v4 drops to zero there, which tints short tables).
SpectrumSamples sample_spectrum(std::span<const float> lambda_nm, std::span<const float> values);

// CIE 1931 XYZ to linear sRGB (IEC 61966-2-1 primaries and D65 white).
RGB xyz_to_linear_srgb(const Vec3& xyz);
// XYZ of an emission spectrum, scaled so that the equal-energy spectrum 1 has Y = 1.
Vec3 spectrum_to_xyz(const SpectrumSamples& s);
RGB reflectance_spectrum_to_rgb(const SpectrumSamples& s);
RGB emission_spectrum_to_rgb(const SpectrumSamples& s);  // luminance 1 (black stays black)
// Planck's law at `kelvin`, as an emitter of luminance 1.
RGB blackbody_to_rgb(float kelvin);

// Piecewise linear through (lambda, value) points, constant beyond the ends.
float interpolate_spectrum(std::span<const float> lambda_nm, std::span<const float> values, float l_nm);
// A named spectrum's colour: glasses their index at 550 nm, metals as reflectance-like,
// illuminants as emission.
RGB named_spectrum_to_rgb(const NamedSpectrum& n);

}  // namespace eyetrace
