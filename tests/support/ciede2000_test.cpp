// The colour-difference helpers of tests/support/ciede2000.h against published values.
#include "ciede2000.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {
namespace EYETRACE_UNITY_ID {

using eyetrace::colour::cie76;
using eyetrace::colour::ciede2000;
using eyetrace::colour::Lab;
using eyetrace::colour::xyz_to_lab;

struct Pair {
  Lab lab1, lab2;
  double de00;
};

// All 34 pairs of Table 1 of G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference
// formula: implementation notes, supplementary test data, and mathematical observations",
// Color Res. Appl. 30(1), 21-30, 2005 (also ciede2000testdata.txt on
// www.ece.rochester.edu/~gsharma/ciede2000/), printed to 4 decimals. Copied from two public
// listings of that table that agree with each other (Argyll CMS's icc test of icmCIE2K and a
// Rust crate's fixture of pairs 1-20). Pairs 7-16 probe the hue seam at 0/360 degrees and the
// zero-chroma hue, 17-34 are the paper's ordinary and near-neutral pairs.
const Pair kSharma2005[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
};

TEST(Ciede2000, MatchesSharmaWuDalal2005TestData) {
  ASSERT_EQ(std::size(kSharma2005), 34u);
  for (size_t i = 0; i < std::size(kSharma2005); ++i) {
    const Pair& p = kSharma2005[i];
    // The table is rounded to 4 decimals: agree to within half a unit of the last one.
    EXPECT_NEAR(ciede2000(p.lab1, p.lab2), p.de00, 0.5e-4) << "pair " << i + 1;
    EXPECT_NEAR(ciede2000(p.lab2, p.lab1), p.de00, 0.5e-4) << "pair " << i + 1 << " reversed";
  }
}

TEST(Ciede2000, IsZeroForEqualColoursAndLightnessOnlyForGreys) {
  for (const Pair& p : kSharma2005) EXPECT_EQ(ciede2000(p.lab1, p.lab1), 0.0);
  // Two greys: only the lightness term, dL / S_L with S_L = 1 + 0.015 (L - 50)^2 / sqrt(20 + (L - 50)^2)
  // at the mean L = 50, where S_L = 1; at mean 70, S_L = 1 + 0.015 * 400 / sqrt(420) = 1.29277.
  EXPECT_NEAR(ciede2000({40, 0, 0}, {60, 0, 0}), 20.0, 1e-12);
  EXPECT_NEAR(ciede2000({65, 0, 0}, {75, 0, 0}), 10.0 / (1.0 + 6.0 / std::sqrt(420.0)), 1e-12);
}

TEST(Cie76, IsEuclideanInLab) { EXPECT_DOUBLE_EQ(cie76({50, 1, 2}, {53, 5, 2}), 5.0); }

TEST(XyzToLab, FollowsCie1976) {
  const std::array<double, 3> white = {0.9505, 1.0, 1.089};
  Lab w = xyz_to_lab(white, white);
  EXPECT_NEAR(w.L, 100.0, 1e-12);
  EXPECT_NEAR(w.a, 0.0, 1e-12);
  EXPECT_NEAR(w.b, 0.0, 1e-12);
  // A grey of luminance 0.18: L* = 116 * 0.18^(1/3) - 16 = 49.4961.
  Lab g = xyz_to_lab({0.18 * white[0], 0.18, 0.18 * white[2]}, white);
  EXPECT_NEAR(g.L, 49.4961, 1e-4);
  EXPECT_NEAR(g.a, 0.0, 1e-12);
  EXPECT_NEAR(g.b, 0.0, 1e-12);
  // Below (6/29)^3 = 0.008856 the linear segment: L* = (29/3)^3 Y = 903.2963 Y.
  EXPECT_NEAR(xyz_to_lab({0.005 * white[0], 0.005, 0.005 * white[2]}, white).L, 4.5165, 1e-4);
  // Chroma signs: more X than the white is red (a* > 0), more Z is blue (b* < 0).
  EXPECT_GT(xyz_to_lab({0.6, 0.5, 0.5 * white[2]}, white).a, 0.0);
  EXPECT_LT(xyz_to_lab({0.5 * white[0], 0.5, 0.7}, white).b, 0.0);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
