// Spectral parameters to RGB (core/spectrum.h): constants, pairs, blackbodies, named spectra
// and the error messages, against published colorimetry.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/cie_tables.h"
#include "core/named_spectra.h"
#include "core/spectrum.h"
#include "scene/params.h"
#include "scene/spectrum_param.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param spectrum_param(std::vector<double> numbers, std::vector<std::string> strings = {},
                     std::string type = "spectrum") {
  Param p;
  p.type = std::move(type);
  p.name = "reflectance";
  p.loc = SourceLoc{"scene.pbrt", 3, 7};
  p.numbers = std::move(numbers);
  p.strings = std::move(strings);
  return p;
}

Vec2 chromaticity(const Vec3& xyz) { return Vec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z); }

Vec3 named_xyz(const char* name) {
  const NamedSpectrum* n = find_named_spectrum(name);
  EXPECT_NE(n, nullptr) << name;
  SpectrumSamples s{};
  for (int i = 0; i < kCieRows; ++i) s[i] = evaluate_named_spectrum(*n, cie_table()[i].lambda_nm);
  return spectrum_to_xyz(s);
}

// The colour a spectrum parameter stands for: emission for blackbodies and illuminants (luminance
// 1), reflectance for everything else.
RGB spectrum_param_to_rgb(const Param& p) {
  const bool emission =
      p.canonical_type() == "blackbody" || (!p.strings.empty() && p.strings[0].rfind("stdillum", 0) == 0);
  const SpectrumType t = emission ? SpectrumType::Illuminant : SpectrumType::Albedo;
  return spectrum_param_value(p, t).to_rgb(t);
}

std::string error_of(const Param& p) {
  try {
    spectrum_param_to_rgb(p);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(CieTable, EqualEnergyWhiteHasEqualTristimulusSums) {
  // The CIE 1931 functions are scaled so that illuminant E has X = Y = Z; the 5 nm table
  // sums to 21.3714 for each (CIE 15, Table of the 1931 observer, column sums).
  double x = 0, y = 0, z = 0;
  for (const auto& r : cie_table()) x += r.x, y += r.y, z += r.z;
  EXPECT_NEAR(x, 21.3714, 1e-3);
  EXPECT_NEAR(y, 21.3714, 1e-3);
  EXPECT_NEAR(z, 21.3715, 1e-3);
}

TEST(CieTable, IlluminantChromaticitiesMatchCie15) {
  // CIE 15:2004 Table T.3 (2-degree observer).
  Vec2 d65 = chromaticity(named_xyz("stdillum-D65"));
  EXPECT_NEAR(d65.x, 0.31272, 2e-4);
  EXPECT_NEAR(d65.y, 0.32903, 2e-4);
  Vec2 d50 = chromaticity(named_xyz("stdillum-D50"));
  EXPECT_NEAR(d50.x, 0.34567, 5e-4);
  EXPECT_NEAR(d50.y, 0.35850, 5e-4);
  Vec2 a = chromaticity(named_xyz("stdillum-A"));
  EXPECT_NEAR(a.x, 0.44757, 5e-4);
  EXPECT_NEAR(a.y, 0.40745, 5e-4);
}

TEST(XyzToSrgb, D65WhiteMapsToUnitRgb) {
  // sRGB's white is D65, XYZ (0.95047, 1, 1.08883) (IEC 61966-2-1).
  RGB w = xyz_to_linear_srgb(Vec3(0.95047f, 1.f, 1.08883f));
  EXPECT_NEAR(w.r, 1.f, 2e-4);
  EXPECT_NEAR(w.g, 1.f, 2e-4);
  EXPECT_NEAR(w.b, 1.f, 2e-4);
  // The red primary (x, y) = (0.64, 0.33) maps to pure red.
  Vec3 red(0.64f / 0.33f, 1.f, 0.03f / 0.33f);
  RGB r = xyz_to_linear_srgb(red);
  EXPECT_NEAR(r.g / r.r, 0.f, 1e-4);
  EXPECT_NEAR(r.b / r.r, 0.f, 1e-4);
}

TEST(SpectrumParam, ConstantIsGrey) {
  RGB c = spectrum_param_to_rgb(spectrum_param({0.5}));
  EXPECT_EQ(c, RGB(0.5f));
}

TEST(SpectrumParam, EqualEnergyPairsGiveEqualRgb) {
  for (double v : {0.25, 0.5, 1.0}) {
    RGB c = spectrum_param_to_rgb(spectrum_param({300, v, 550, v, 900, v}));
    EXPECT_NEAR(c.r, v, 1e-5);
    EXPECT_NEAR(c.g, v, 1e-5);
    EXPECT_NEAR(c.b, v, 1e-5);
  }
  // A table that covers less than 380..780 nm is held constant beyond its ends.
  RGB c = spectrum_param_to_rgb(spectrum_param({400, 0.5, 700, 0.5}));
  EXPECT_NEAR(c.r, 0.5f, 1e-5);
  EXPECT_NEAR(c.b, 0.5f, 1e-5);
}

TEST(SpectrumParam, LongWavelengthsLookRed) {
  RGB c = spectrum_param_to_rgb(spectrum_param({380, 0, 599, 0, 601, 1, 780, 1}));
  EXPECT_GT(c.r, 4.f * std::abs(c.g));
  EXPECT_GT(c.r, 4.f * std::abs(c.b));
}

TEST(SpectrumParam, Blackbody6504KIsSlightlyMagentaNotWhite) {
  // D65 lies 0.0032 in CIE 1960 uv off the Planckian locus, so a 6504 K blackbody of luminance 1
  // is linear sRGB (1.04282, 0.98379, 1.03511), not white: Planck's law, the CIE 1931 functions
  // and the IEC 61966-2-1 matrix, `/usr/bin/python3 tools/blackbody_reference.py` (no eyetrace
  // code). The same 5 nm sums here; the film's matrix (Lindbloom's) and its per-channel scaling
  // of the tabulated D65 to exactly white differ from the IEC matrix by about 1e-4.
  RGB c = spectrum_param_to_rgb(spectrum_param({6504}, {}, "blackbody"));
  EXPECT_NEAR(luminance(c), 1.f, 1e-4);
  const float want[3] = {1.04282f, 0.98379f, 1.03511f};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], want[i], 1e-3f * want[i]) << i;
}

TEST(SpectrumParam, BlackbodyChromaticityFollowsPlanckianLocus) {
  // Planckian locus chromaticities (Wyszecki & Stiles, Table 1(3.11)): 2856 K is
  // illuminant A (0.4476, 0.4074); 10000 K is (0.2807, 0.2884).
  auto xy = [](double t) {
    RGB rgb = spectrum_param_to_rgb(spectrum_param({t}, {}, "blackbody"));
    // Back to XYZ through the inverse of the published XYZ -> sRGB matrix (column-major).
    glm::mat3 m(3.2404542f, -0.9692660f, 0.0556434f, -1.5371385f, 1.8760108f, -0.2040259f, -0.4985314f, 0.0415560f,
                1.0572252f);
    Vec3 xyz = glm::inverse(m) * rgb;
    return chromaticity(xyz);
  };
  Vec2 a = xy(2856.0);
  EXPECT_NEAR(a.x, 0.4476f, 1e-3f);
  EXPECT_NEAR(a.y, 0.4074f, 1e-3f);
  Vec2 b = xy(10000.0);
  EXPECT_NEAR(b.x, 0.2807f, 1e-3f);
  EXPECT_NEAR(b.y, 0.2884f, 1e-3f);
}

TEST(SpectrumParam, Stdillum65IsWhite) {
  RGB c = spectrum_param_to_rgb(spectrum_param({}, {"stdillum-D65"}));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], 1.f, 2e-3f);
}

TEST(SpectrumParam, GlassIndexFollowsSchottData) {
  // Schott BK7: n_e = 1.51872 at 546.07 nm, n_d = 1.51680 at 587.56 nm, n_F' = 1.52283 at
  // 479.99 nm (Schott datasheet).
  Spectrum bk7 = spectrum_param_value(spectrum_param({}, {"glass-BK7"}), SpectrumType::Unbounded).spectrum;
  EXPECT_NEAR(bk7(546.07f), 1.51872f, 5e-4f);
  EXPECT_NEAR(bk7(587.56f), 1.51680f, 5e-4f);
  EXPECT_NEAR(bk7(479.99f), 1.52283f, 5e-4f);
  EXPECT_NEAR(spectrum_param_at(spectrum_param({}, {"glass-BK7"}), 587.56f), 1.51680f, 5e-4f);
}

TEST(SpectrumParam, EveryNamedSpectrumConverts) {
  for (const auto& name : named_spectrum_names()) {
    RGB c = spectrum_param_to_rgb(spectrum_param({}, {name}));
    EXPECT_TRUE(is_finite(c)) << name;
    // MgO is a dielectric: pbrt-v4's k table for it is 0 above 364 nm (1e-6 below).
    if (name == "metal-MgO-k")
      EXPECT_EQ(max_component(c), 0.f) << name;
    else
      EXPECT_GT(max_component(c), 0.f) << name;
  }
  for (const char* name : {"metal-Ag-eta", "metal-Ag-k", "metal-Al-eta", "metal-Al-k", "metal-Au-eta", "metal-Au-k",
                           "metal-Cu-eta", "metal-Cu-k", "glass-BK7", "stdillum-D65"})
    EXPECT_NE(find_named_spectrum(name), nullptr) << name;
}

TEST(SpectrumParam, UnknownNamesListKnownOnes) {
  std::string e = error_of(spectrum_param({}, {"metal-Cu-etta"}));
  EXPECT_NE(e.find("scene.pbrt:3:7"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"metal-Cu-eta\""), std::string::npos) << e;
  EXPECT_NE(e.find("glass-BK7"), std::string::npos) << e;
  EXPECT_NE(e.find("stdillum-D65"), std::string::npos) << e;
}

TEST(SpectrumParam, MalformedPairsAreErrors) {
  EXPECT_NE(error_of(spectrum_param({400, 0.5, 500})).find("pairs"), std::string::npos);
  EXPECT_NE(error_of(spectrum_param({500, 0.5, 400, 0.5})).find("increasing"), std::string::npos);
  EXPECT_NE(error_of(spectrum_param({10}, {}, "blackbody")).find("outside"), std::string::npos);
}

TEST(SpectrumParamAt, InterpolatesPairs) {
  Param p = spectrum_param({500, 1.4, 600, 1.6});
  EXPECT_NEAR(spectrum_param_at(p, 550.f), 1.5f, 1e-6f);
  EXPECT_NEAR(spectrum_param_at(p, 400.f), 1.4f, 1e-6f);
  EXPECT_NEAR(spectrum_param_at(spectrum_param({1.33}), 550.f), 1.33f, 1e-6f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
