// Bradford white balance against Lindbloom's published matrices, and pbrt-v4's white balance
// illuminant against the CIE's published chromaticities of the D illuminants.
#include "core/white_balance.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include "core/spectrum.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

void expect_matrix_near(const glm::dmat3& m, const double (&want)[3][3], double tol) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c][r], want[r][c], tol) << "row " << r << " column " << c;
}

// Bruce Lindbloom, "Chromatic Adaptation" (brucelindbloom.com, Eqn_ChromAdapt), Bradford rows,
// with his reference whites D65 (0.95047, 1, 1.08883), D50 (0.96422, 1, 0.82521) and
// A (1.09850, 1, 0.35585); printed to 7 decimals.
const glm::dvec3 kD65(0.95047, 1.0, 1.08883), kD50(0.96422, 1.0, 0.82521), kA(1.09850, 1.0, 0.35585);

TEST(WhiteBalance, BradfordMatchesLindbloomsTables) {
  expect_matrix_near(
      bradford_adaptation(kD65, kD50),
      {{1.0478112, 0.0228866, -0.0501270}, {0.0295424, 0.9904844, -0.0170491}, {-0.0092345, 0.0150436, 0.7521316}},
      1e-7);
  expect_matrix_near(
      bradford_adaptation(kD50, kD65),
      {{0.9555766, -0.0230393, 0.0631636}, {-0.0282895, 1.0099416, 0.0210077}, {0.0122982, -0.0204830, 1.3299098}},
      1e-7);
  expect_matrix_near(
      bradford_adaptation(kA, kD65),
      {{0.8446965, -0.1179225, 0.3948108}, {-0.1366303, 1.1041226, 0.1291718}, {0.0798489, -0.1348999, 3.1924009}},
      1e-7);
  // Lindbloom's inverse cone matrix.
  expect_matrix_near(
      bradford_xyz_from_lms(),
      {{0.9869929, -0.1470543, 0.1599627}, {0.4323053, 0.5183603, 0.0492912}, {-0.0085287, 0.0400428, 0.9684867}},
      1e-7);
}

// By construction (von Kries): the source white goes to the target white, luminance kept; the
// same whites give the identity; given as chromaticities the result is the same.
TEST(WhiteBalance, MapsTheSourceWhiteToTheTargetWhite) {
  const glm::dvec3 out = bradford_adaptation(kA, kD65) * kA;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], kD65[i], 1e-12);
  const glm::dmat3 same = bradford_adaptation(kD50, kD50);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(same[c][r], r == c ? 1.0 : 0.0, 1e-12);
  const glm::dmat3 by_xy = bradford_adaptation(xy_from_xyz(kA), xy_from_xyz(kD65));
  const glm::dmat3 by_xyz = bradford_adaptation(kA, kD65);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(by_xy[c][r], by_xyz[c][r], 1e-12);
}

glm::dvec2 illuminant_xy(double kelvin) {
  glm::dvec3 xyz(0.0);
  for (int l = 360; l <= 830; ++l) xyz += glm::dvec3(cie_xyz_bar(float(l))) * white_balance_illuminant(kelvin, l);
  return xy_from_xyz(xyz);
}

// pbrt-v4's illuminant at T is the CIE D illuminant at T * 1.4388 / 1.4380, which is how the
// CIE defines D50, D65 and D75 from 5000, 6500 and 7500 K; their chromaticities for the
// 2-degree observer (CIE 15:2004): D50 (0.34567, 0.35850), D65 (0.31271, 0.32902),
// D75 (0.29902, 0.31485). 7500 K takes the locus' second branch (above 7000 K). The 5 nm tables
// interpolated to 1 nm leave about 1e-4.
TEST(WhiteBalance, IlluminantIsTheCieDaylightAboveFourThousandKelvin) {
  const struct {
    double kelvin, x, y;
  } cases[] = {{5000, 0.34567, 0.35850}, {6500, 0.31271, 0.32902}, {7500, 0.29902, 0.31485}};
  for (const auto& c : cases) {
    const glm::dvec2 xy = illuminant_xy(c.kelvin);
    EXPECT_NEAR(xy.x, c.x, 3e-4) << c.kelvin << " K";
    EXPECT_NEAR(xy.y, c.y, 3e-4) << c.kelvin << " K";
  }
}

// Below 4000 K a blackbody at the CCT: Planck's law in shape, and at 2856 K * 1.4380 / 1.4388
// (so that the CCT is 2856 K) CIE illuminant A's chromaticity (0.44757, 0.40745; CIE 15).
TEST(WhiteBalance, IlluminantIsABlackbodyBelowFourThousandKelvin) {
  const double t = 3000.0, cct = t * 1.4388 / 1.4380;
  EXPECT_NEAR(white_balance_illuminant(t, 450.0) / white_balance_illuminant(t, 650.0),
              planck(450.0, cct) / planck(650.0, cct), 1e-12);
  const glm::dvec2 xy = illuminant_xy(2856.0 * 1.4380 / 1.4388);
  EXPECT_NEAR(xy.x, 0.44757, 3e-4);
  EXPECT_NEAR(xy.y, 0.40745, 3e-4);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
