// Hero-wavelength sampling (core/sampled_spectrum.h) and the film's colorimetry
// (core/spectrum.h): the sampling density is normalised and the one the wavelengths are drawn
// with, and the Monte Carlo XYZ of known spectra converges to the CIE integrals.
#include "core/sampled_spectrum.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/spectrum.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(SampledWavelengths, DensityIsNormalisedOverTheVisibleRange) {
  // Midpoint rule at 0.01 nm over [360, 830] nm.
  double sum = 0;
  for (int i = 0; i < 47000; ++i) sum += visible_wavelength_pdf(360.f + 0.01f * (i + 0.5f)) * 0.01;
  EXPECT_NEAR(sum, 1.0, 1e-4);
}

TEST(SampledWavelengths, FourStratifiedWavelengthsWithTheirDensity) {
  for (float u : {0.f, 0.1f, 0.37f, 0.5f, 0.99f}) {
    SampledWavelengths w = SampledWavelengths::sample_visible(u);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      float up = u + float(i) / kSpectrumSamples;
      if (up >= 1.f) up -= 1.f;
      EXPECT_NEAR(w[i], sample_visible_wavelength(up), 2e-3f) << u << " " << i;
      // The tabulated sampler's density is the formula's within 0.5 % (the widest cells, in the tails).
      EXPECT_NEAR(w.pdf()[i], visible_wavelength_pdf(w[i]), 5e-3f * visible_wavelength_pdf(w[i])) << u;
      EXPECT_GE(w[i], kLambdaMin);
      EXPECT_LE(w[i], kLambdaMax);
    }
  }
}

TEST(SampledWavelengths, TerminatingKeepsTheHeroAndTheEstimateUnbiased) {
  SampledWavelengths w = SampledWavelengths::sample_visible(0.3f);
  const float hero_pdf = w.pdf()[0];
  w.terminate_secondary();
  EXPECT_TRUE(w.secondary_terminated());
  EXPECT_FLOAT_EQ(w.pdf()[0], hero_pdf / kSpectrumSamples);
  for (int i = 1; i < kSpectrumSamples; ++i) EXPECT_EQ(w.pdf()[i], 0.f);
}

// The film's estimate of Y for the constant spectrum 1 is 1, and of the white illuminant is
// 1, averaged over stratified wavelength sets, with and without terminated secondaries.
TEST(SampledToXyz, ConvergesToTheCieIntegrals) {
  for (bool terminate : {false, true}) {
    const int n = 20000;
    Vec3 e(0.f), w(0.f);
    for (int k = 0; k < n; ++k) {
      SampledWavelengths l = SampledWavelengths::sample_visible((k + 0.5f) / n);
      if (terminate) l.terminate_secondary();
      SampledSpectrum white;
      for (int i = 0; i < kSpectrumSamples; ++i) white[i] = white_illuminant(l[i]);
      e += sampled_to_xyz(SampledSpectrum(1.f), l) / float(n);
      w += sampled_to_xyz(white, l) / float(n);
    }
    EXPECT_NEAR(e.y, 1.f, 2e-4f) << terminate;
    EXPECT_NEAR(w.y, 1.f, 2e-4f) << terminate;
    // CIE 1931: equal energy has X = Y = Z (the 5 nm table's sums agree to 1e-5).
    EXPECT_NEAR(e.x, 1.f, 2e-4f);
    EXPECT_NEAR(e.z, 1.f, 2e-4f);
    // The white comes out as linear sRGB (1, 1, 1).
    RGB rgb = xyz_to_linear_srgb(w);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.f, 1e-3f) << terminate << " " << c;
  }
}

// The white that the film's normalised splats scale by: what sampled_to_xyz gives the constant
// spectrum 1 on average (stratified over the wavelength sample, hero-only as well), and CIE
// 1931's equal-energy white, X = Y = Z (the 5 nm table's sums agree to 1e-5, its trapezoid
// integrals to 1.4e-4).
TEST(EqualEnergyXyz, IsTheMeanOfSampledToXyzOfOne) {
  const Vec3 w = equal_energy_xyz();
  EXPECT_EQ(w.y, 1.f);
  EXPECT_NEAR(w.x, 1.f, 2e-4f);
  EXPECT_NEAR(w.z, 1.f, 2e-4f);
  for (bool terminate : {false, true}) {
    const int n = 1 << 16;
    glm::dvec3 mean(0.0);
    for (int k = 0; k < n; ++k) {
      SampledWavelengths l = SampledWavelengths::sample_visible((k + 0.5f) / n);
      if (terminate) l.terminate_secondary();
      mean += glm::dvec3(sampled_to_xyz(SampledSpectrum(1.f), l)) / double(n);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], w[c], 5e-5) << terminate << " " << c;
  }
}

// A dispersive eye's splat forms one wavelength's colour at a time (Film::add_wavelength_splats):
// wavelength_to_rgb must be sampled_to_rgb of a spectrum zero at the other wavelengths, to float
// rounding, over the whole sampled range and beyond the CIE table (where both are 0).
TEST(WavelengthToRgb, IsSampledToRgbOfOneWavelength) {
  int compared = 0;
  for (int j = 0; j < 4000; ++j) {
    const SampledWavelengths l = SampledWavelengths::sample_visible((j + 0.5f) / 4000.f);
    const SampledSpectrum pdf = l.pdf();
    for (int k = 0; k < kSpectrumSamples; ++k) {
      SampledSpectrum one(0.f);
      one[k] = 0.25f + 3.f * float(j % 7);
      const RGB want = sampled_to_rgb(one, l), got = wavelength_to_rgb(l[k], one[k] / pdf[k]);
      const float scale = std::max({std::abs(want.r), std::abs(want.g), std::abs(want.b)});
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-6f * scale) << l[k] << " nm, channel " << c;
      compared += scale > 0.f;
    }
  }
  EXPECT_GT(compared, 12000);  // most of 360-830 nm is inside the table (380-780 nm)
  EXPECT_EQ(wavelength_to_rgb(370.f, 1.f), RGB(0.f));
  EXPECT_EQ(wavelength_to_rgb(800.f, 1.f), RGB(0.f));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
