// Hero-wavelength sampling (core/sampled_spectrum.h) and the film's colorimetry
// (core/spectrum.h): the sampling density is normalised and the one the wavelengths are drawn
// with, and the Monte Carlo XYZ of known spectra converges to the CIE integrals.
#include "core/sampled_spectrum.h"

#include <gtest/gtest.h>

#include "core/spectrum.h"

namespace eyetrace {
namespace {

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

}  // namespace
}  // namespace eyetrace
