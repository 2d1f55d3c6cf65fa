// White balance by von Kries adaptation in the Bradford cone space: the XYZ-to-XYZ matrix that
// maps a source white to a target white by scaling each Bradford "cone" response (L, M, S)
// separately, as pbrt-v4's WhiteBalance() does (src/pbrt/util/color.h) and as Lindbloom tabulates
// ("Chromatic Adaptation", brucelindbloom.com). Also the CIE daylight chromaticity and the
// illuminant pbrt-v4 balances for at a colour temperature.
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace eyetrace {

// XYZ of the chromaticity xy at Y = 1.
glm::dvec3 xyz_from_xy(glm::dvec2 xy);
// The chromaticity (x, y) of XYZ; (0, 0) for black.
glm::dvec2 xy_from_xyz(glm::dvec3 xyz);

// The Bradford matrix M_A (Lam 1985) and its inverse, as Lindbloom gives them.
const glm::dmat3& bradford_lms_from_xyz();
const glm::dmat3& bradford_xyz_from_lms();

// XYZ to XYZ: M_A^-1 diag(LMS(target) / LMS(source)) M_A, whites given as XYZ (any Y: each is
// taken at Y = 1, so that luminance is kept) or as chromaticities.
glm::dmat3 bradford_adaptation(glm::dvec3 source_white_xyz, glm::dvec3 target_white_xyz);
glm::dmat3 bradford_adaptation(glm::dvec2 source_white_xy, glm::dvec2 target_white_xy);

// The spectrum pbrt-v4 white balances for at `kelvin` (Spectra::D in src/pbrt/util/spectrum.cpp):
// the temperature becomes a CCT on today's c2 (kelvin * 1.4388 / 1.4380); below 4000 K the CIE
// D series is undefined and a blackbody at that CCT stands in, otherwise the CIE daylight
// S0 + M1 S1 + M2 S2 at the CCT's daylight-locus chromaticity (CIE 15). Relative power: only
// its shape matters to white balance. 0 outside the CIE daylight table's 380-780 nm for the D
// series (pbrt-v4's table reaches 300-830 nm, where the colour-matching functions are below 4e-4
// of their peak).
double white_balance_illuminant(double kelvin, double lambda_nm);

}  // namespace eyetrace
