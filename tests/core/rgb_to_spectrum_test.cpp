// The RGB -> spectrum table (core/rgb_to_spectrum.h), checked by colorimetry done here, apart
// from the generator: every spectrum is integrated against the CIE 1931 observer under D65 by
// the trapezoidal rule at 0.5 nm (the generator uses Gauss-Legendre nodes), the target RGB
// goes to XYZ by the matrix published in IEC 61966-2-1 (the generator derives its own from the
// primaries and the tables' D65), and the two are compared with CIEDE2000 in CIELAB, each
// relative to its own white.
#include "core/rgb_to_spectrum.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "../support/ciede2000.h"
#include "../support/color_checker.h"
#include "core/cie_tables.h"

namespace {
namespace EYETRACE_UNITY_ID {

using eyetrace::RGBToSpectrumTable;
using eyetrace::SigmoidPolynomial;
using eyetrace::colour::ciede2000;
using eyetrace::colour::Lab;
using eyetrace::colour::xyz_to_lab;
using Xyz = std::array<double, 3>;

constexpr float kInf = std::numeric_limits<float>::infinity();

// XYZ of a reflectance under D65: the trapezoidal rule at 0.5 nm over 380..780 nm, the CIE
// table's 5 nm rows interpolated linearly, scaled so that the perfect reflector has Y = 1.
// (Plain 5 nm sums are not enough here: for the steep spectra of saturated colours they are
// off by up to 0.05 CIEDE2000, more than the table's own error.)
struct Weight {
  float lambda;
  double x, y, z;
};
const std::vector<Weight>& weights() {
  static const std::vector<Weight> w = [] {
    const auto& rows = eyetrace::cie_table();
    std::vector<Weight> out;
    double y_white = 0.0;
    constexpr int kSteps = 800;  // 0.5 nm
    for (int i = 0; i <= kSteps; ++i) {
      double lambda = 380.0 + 400.0 * i / kSteps, u = (lambda - 380.0) / 5.0;
      int r = std::min(int(u), eyetrace::kCieRows - 2);
      double f = u - r, trapezoid = (i == 0 || i == kSteps) ? 0.5 : 1.0;
      auto lerp = [f](float a, float b) { return (1.0 - f) * a + f * b; };
      const eyetrace::CieRow &a = rows[r], &b = rows[r + 1];
      double e = trapezoid * lerp(a.d65, b.d65);
      out.push_back({float(lambda), e * lerp(a.x, b.x), e * lerp(a.y, b.y), e * lerp(a.z, b.z)});
      y_white += out.back().y;
    }
    for (Weight& v : out) v.x /= y_white, v.y /= y_white, v.z /= y_white;
    return out;
  }();
  return w;
}

template <typename Spectrum>
Xyz reflectance_xyz(const Spectrum& s) {
  double x = 0, y = 0, z = 0;
  for (const Weight& w : weights()) {
    double v = s(w.lambda);
    x += v * w.x;
    y += v * w.y;
    z += v * w.z;
  }
  return {x, y, z};
}

const Xyz& spectral_white() {
  static const Xyz white = reflectance_xyz([](float) { return 1.0; });
  return white;
}

// Linear sRGB -> XYZ, the matrix of IEC 61966-2-1:1999 (D65 white), to its published 4 decimals.
Xyz srgb_to_xyz(double r, double g, double b) {
  return {0.4124 * r + 0.3576 * g + 0.1805 * b, 0.2126 * r + 0.7152 * g + 0.0722 * b,
          0.0193 * r + 0.1192 * g + 0.9505 * b};
}

// The sRGB transfer function (IEC 61966-2-1), 8-bit code -> linear.
double srgb_decode(int code) {
  double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// CIEDE2000 between a linear sRGB colour and the colour of its spectrum from the table.
double round_trip_de00(float r, float g, float b) {
  SigmoidPolynomial s = RGBToSpectrumTable::srgb()(glm::vec3(r, g, b));
  Lab target = xyz_to_lab(srgb_to_xyz(r, g, b), srgb_to_xyz(1, 1, 1));
  Lab got = xyz_to_lab(reflectance_xyz(s), spectral_white());
  return ciede2000(target, got);
}

// 24-bit uniform floats in [0, 1] from a generator independent of the renderer.
class Uniform {
 public:
  explicit Uniform(uint64_t seed) : rng_(seed) {}
  float next() { return float(rng_() >> 40) * 0x1p-24f; }
  // r, g, b in this order (the order of evaluation of function arguments is unspecified).
  glm::vec3 next_rgb() {
    float r = next(), g = next();
    return glm::vec3(r, g, next());
  }

 private:
  std::mt19937_64 rng_;
};

// Which of the three rotations of a colour to use, from the low bits of one of its components.
int n_rotation(const glm::vec3& c) { return int(c.g * 16777216.f) % 3; }

// ---- The sigmoid polynomial itself.

TEST(SigmoidPolynomial, EvaluatesTheSigmoidOfTheQuadratic) {
  // S(x) = 1/2 + x / (2 sqrt(1 + x^2)): S(0) = 1/2, S(+-1) = 1/2 +- 1/(2 sqrt 2) = 0.853553 / 0.146447.
  EXPECT_FLOAT_EQ(SigmoidPolynomial{}(500.f), 0.5f);
  EXPECT_NEAR((SigmoidPolynomial{0, 0, 1})(400.f), 0.8535534, 1e-6);
  EXPECT_NEAR((SigmoidPolynomial{0, 0, -1})(400.f), 0.1464466, 1e-6);
  // p(lambda) = 1e-4 (lambda - 550)^2 - 1: p(550) = -1, p(650) = 0, p(450) = 0, p(750) = 3.
  SigmoidPolynomial s{1e-4f, -0.11f, 29.25f};
  EXPECT_NEAR(s(550.f), 0.1464466, 1e-5);
  EXPECT_NEAR(s(650.f), 0.5, 1e-5);
  EXPECT_NEAR(s(450.f), 0.5, 1e-5);
  EXPECT_NEAR(s(750.f), 0.5 + 3.0 / (2.0 * std::sqrt(10.0)), 1e-5);
}

TEST(SigmoidPolynomial, InfiniteAndHugeArgumentsGiveZeroOrOneWithoutNaN) {
  for (float lambda : {360.f, 555.f, 830.f}) {
    EXPECT_EQ((SigmoidPolynomial{0, 0, -kInf})(lambda), 0.f);
    EXPECT_EQ((SigmoidPolynomial{0, 0, kInf})(lambda), 1.f);
    EXPECT_EQ((SigmoidPolynomial{kInf, 0, 0})(lambda), 1.f);  // pbrt-style infinite c0
    EXPECT_EQ((SigmoidPolynomial{-kInf, 0, 0})(lambda), 0.f);
    EXPECT_EQ((SigmoidPolynomial{0, 0, 1e30f})(lambda), 1.f);
    EXPECT_EQ((SigmoidPolynomial{0, 0, -1e30f})(lambda), 0.f);
    EXPECT_NEAR((SigmoidPolynomial{0, 0, -1e4f})(lambda), 0.f, 1e-7f);
  }
  EXPECT_EQ(SigmoidPolynomial::sigmoid(std::numeric_limits<float>::quiet_NaN()), 0.f);
  EXPECT_EQ((SigmoidPolynomial{0, 0, -kInf}).max_value(), 0.f);
  EXPECT_EQ((SigmoidPolynomial{0, 0, kInf}).max_value(), 1.f);
  EXPECT_EQ((SigmoidPolynomial{kInf, 0, 0}).max_value(), 1.f);
}

TEST(SigmoidPolynomial, MaxValueIsTheMaximumOver360To830) {
  // A peak inside (the vertex at 550 nm, p = 0 there) and peaks at either end.
  EXPECT_NEAR((SigmoidPolynomial{-1e-4f, 0.11f, -30.25f}).max_value(), 0.5f, 1e-4f);
  SigmoidPolynomial rising{0, 0.01f, -6.f}, falling{0, -0.01f, 6.f};
  EXPECT_FLOAT_EQ(rising.max_value(), rising(830.f));
  EXPECT_FLOAT_EQ(falling.max_value(), falling(360.f));
  // And against a dense search, for the spectra of random colours.
  Uniform u(7);
  for (int n = 0; n < 200; ++n) {
    SigmoidPolynomial s = RGBToSpectrumTable::srgb()(u.next_rgb());
    float dense = 0.f;
    for (int i = 0; i <= 4700; ++i) dense = std::max(dense, s(360.f + 0.1f * float(i)));
    // Equal but for float rounding in the polynomial (whose terms cancel to ~1e-6 relative).
    EXPECT_NEAR(s.max_value(), dense, 2e-5f);
  }
}

// ---- The table.

TEST(RGBToSpectrum, BlackIsZeroWhiteIsOneEverywhere) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  SigmoidPolynomial black = table(glm::vec3(0.f)), white = table(glm::vec3(1.f));
  for (int lambda = 360; lambda <= 830; ++lambda) {
    EXPECT_EQ(black(float(lambda)), 0.f) << lambda;
    EXPECT_EQ(white(float(lambda)), 1.f) << lambda;
  }
  EXPECT_EQ(black.max_value(), 0.f);
  EXPECT_EQ(white.max_value(), 1.f);
}

TEST(RGBToSpectrum, GreysAreConstant) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  for (float g : {1e-7f, 1e-4f, 0.01f, 0.18f, 0.5f, 0.75f, 0.9f, 0.999f, 0.9999999f}) {
    SigmoidPolynomial s = table(glm::vec3(g));
    for (int lambda = 360; lambda <= 830; lambda += 5) EXPECT_NEAR(s(float(lambda)), g, 1e-4f) << g << " " << lambda;
  }
}

TEST(RGBToSpectrum, NearGreysAreNearlyConstant) {
  // Off the exact-grey path, through the table: within the colour difference itself.
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  for (float g : {0.05f, 0.18f, 0.5f, 0.9f}) {
    for (glm::vec3 d : {glm::vec3(1e-4f, 0, 0), glm::vec3(0, 0, -1e-4f), glm::vec3(0, 1e-4f, 1e-4f)}) {
      SigmoidPolynomial s = table(glm::vec3(g) + d);
      for (int lambda = 380; lambda <= 780; lambda += 5) EXPECT_NEAR(s(float(lambda)), g, 1e-3f) << g << " " << lambda;
    }
  }
}

TEST(RGBToSpectrum, ClampsInputsToTheUnitCube) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  auto same = [](const SigmoidPolynomial& a, const SigmoidPolynomial& b) {
    return a.c0 == b.c0 && a.c1 == b.c1 && a.c2 == b.c2;
  };
  EXPECT_TRUE(same(table(glm::vec3(2.f, 0.5f, -1.f)), table(glm::vec3(1.f, 0.5f, 0.f))));
  EXPECT_TRUE(same(table(glm::vec3(kInf, 0.25f, 0.75f)), table(glm::vec3(1.f, 0.25f, 0.75f))));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(same(table(glm::vec3(nan, 0.25f, 0.75f)), table(glm::vec3(0.f, 0.25f, 0.75f))));
  EXPECT_EQ(table(glm::vec3(nan)).max_value(), 0.f);
  EXPECT_EQ(table(glm::vec3(3.f)).max_value(), 1.f);
}

TEST(RGBToSpectrum, ColorCheckerRoundTripsBelowOneCiede2000) {
  double worst = 0.0, sum = 0.0;
  std::string worst_name;
  for (const eyetrace::test::Patch& p : eyetrace::test::kColorChecker) {
    float r = float(srgb_decode(p.r)), g = float(srgb_decode(p.g)), b = float(srgb_decode(p.b));
    double de = round_trip_de00(r, g, b);
    EXPECT_LT(de, 1.0) << p.name;  // imperceptible
    // Measured at resolution 64: max 0.054 (foliage), mean 0.020, nearly all of it the
    // trilinear interpolation of the coefficients (at the table's nodes it is below 0.02).
    EXPECT_LT(de, 0.1) << p.name;
    sum += de;
    if (de > worst) worst = de, worst_name = p.name;
  }
  std::printf("[ stats    ] ColorChecker round trip CIEDE2000: max %.4f (%s), mean %.4f\n", worst, worst_name.c_str(),
              sum / 24.0);
  RecordProperty("max_de00", std::to_string(worst));
}

TEST(RGBToSpectrum, RandomColoursRoundTripAndStayBounded) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  constexpr int kColours = 4096;
  Uniform u(2019);
  double worst = 0.0, sum = 0.0;
  glm::vec3 worst_rgb(0.f);
  std::vector<double> des;
  for (int n = 0; n < kColours; ++n) {
    glm::vec3 rgb = u.next_rgb();
    double de = round_trip_de00(rgb.r, rgb.g, rgb.b);
    sum += de;
    des.push_back(de);
    if (de > worst) worst = de, worst_rgb = rgb;
    // A reflectance: within [0, 1] at every wavelength of 360..830 nm, below its max_value().
    SigmoidPolynomial s = table(rgb);
    float m = s.max_value();
    ASSERT_LE(m, 1.f);
    for (int lambda = 360; lambda <= 830; ++lambda) {
      float v = s(float(lambda));
      ASSERT_GE(v, 0.f) << rgb.r << " " << rgb.g << " " << rgb.b << " at " << lambda;
      ASSERT_LE(v, m + 2e-5f) << rgb.r << " " << rgb.g << " " << rgb.b << " at " << lambda;
    }
  }
  std::sort(des.begin(), des.end());
  const double p99 = des[size_t(0.99 * kColours)];
  std::printf(
      "[ stats    ] %d random linear sRGB round trip CIEDE2000: max %.4f at (%.4f, %.4f, %.4f), 99th percentile %.4f, "
      "mean %.5f\n",
      kColours, worst, worst_rgb.r, worst_rgb.g, worst_rgb.b, p99, sum / kColours);
  RecordProperty("max_de00", std::to_string(worst));
  // Measured at resolution 64: max 0.293 (a saturated red), 99th percentile 0.048, mean 0.011.
  // The largest errors are rare and sit in two corners of the cube (see the dense sweep below).
  EXPECT_LT(worst, 1.0);
  EXPECT_LT(p99, 0.1);
  EXPECT_LT(sum / kColours, 0.02);
}

// Where the largest round-trip errors are: 200 000 uniform colours and 100 000 from each of the
// two regions where the coefficients change fastest between the table's nodes (bright colours
// with two components near 1, where the fitted polynomial switches from a hump to a valley
// within one cell; saturated reds, blues and greens). Seconds in a release build, so it is
// disabled; run it with --gtest_also_run_disabled_tests --gtest_filter='*DenseSweep*'.
TEST(RGBToSpectrum, DISABLED_DenseSweep) {
  Uniform u(1);
  auto sweep = [&](const char* name, auto colour) {
    std::vector<double> des;
    double worst = 0.0;
    glm::vec3 worst_rgb(0.f);
    for (int n = 0; n < (name[0] == 'u' ? 200000 : 100000); ++n) {
      glm::vec3 rgb = colour();
      double de = round_trip_de00(rgb.r, rgb.g, rgb.b);
      des.push_back(de);
      if (de > worst) worst = de, worst_rgb = rgb;
    }
    std::sort(des.begin(), des.end());
    std::printf("[ stats    ] %-10s max %.3f at (%.5f, %.5f, %.5f), 99.9th percentile %.3f, mean %.4f\n", name, worst,
                worst_rgb.r, worst_rgb.g, worst_rgb.b, des[des.size() * 999 / 1000],
                std::accumulate(des.begin(), des.end(), 0.0) / double(des.size()));
    return worst;
  };
  double uniform = sweep("uniform", [&] { return u.next_rgb(); });
  double bright = sweep("bright", [&] {
    glm::vec3 c = u.next_rgb();
    glm::vec3 rgb(1.f - 3e-3f * c.r, 0.9f + 0.1f * c.g, 0.9f + 0.1f * c.b);
    return glm::vec3(rgb[n_rotation(c)], rgb[(n_rotation(c) + 1) % 3], rgb[(n_rotation(c) + 2) % 3]);
  });
  double saturated = sweep("saturated", [&] {
    glm::vec3 c = u.next_rgb();
    glm::vec3 rgb(c.r, 0.05f * c.g, 0.05f * c.b);
    return glm::vec3(rgb[n_rotation(c)], rgb[(n_rotation(c) + 1) % 3], rgb[(n_rotation(c) + 2) % 3]);
  });
  // Measured at resolution 64: uniform max 0.505 (99.9th percentile 0.140), bright max 1.277
  // (0.887), saturated max 0.572 (0.493). The bright corner is the one place above 1.
  EXPECT_LT(uniform, 1.0);
  EXPECT_LT(bright, 2.0);
  EXPECT_LT(saturated, 1.0);
}

TEST(RGBToSpectrum, TableNodesRoundTrip) {
  // At the table's own nodes (no interpolation): the optimiser's fit, the float coefficients
  // and the difference of quadratures and of white points only.
  const int res = RGBToSpectrumTable::srgb().resolution();
  ASSERT_GE(res, 2);
  auto smoothstep = [](double x) { return x * x * (3.0 - 2.0 * x); };
  double worst = 0.0;
  for (int m = 0; m < 3; ++m) {
    for (int k = 1; k < res; k += 3) {
      float z = float(smoothstep(smoothstep(double(k) / (res - 1))));
      for (int j = 0; j < res; j += 5) {
        for (int i = 0; i < res; i += 5) {
          float rgb[3];
          rgb[m] = z;
          rgb[(m + 1) % 3] = float(double(i) / (res - 1)) * z;
          rgb[(m + 2) % 3] = float(double(j) / (res - 1)) * z;
          double de = round_trip_de00(rgb[0], rgb[1], rgb[2]);
          worst = std::max(worst, de);
          // Measured at resolution 64: max 0.017.
          ASSERT_LT(de, 0.05) << rgb[0] << " " << rgb[1] << " " << rgb[2];
        }
      }
    }
  }
  std::printf("[ stats    ] table nodes round trip CIEDE2000: max %.4f\n", worst);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
