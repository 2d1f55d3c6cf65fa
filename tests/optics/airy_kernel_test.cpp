// The Airy kernel (optics/airy_kernel.h) against the Airy pattern's closed forms: the intensity
// (2 J1(v) / v)^2 (Airy 1835), Rayleigh's energy within v, 1 - J0(v)^2 - J1(v)^2 (Rayleigh 1881;
// 83.8 % inside the first dark ring at v = 3.8317), the truncation at a dark ring, and its
// sampler by a Kolmogorov-Smirnov test against the CDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "../support/unity_id.h"
#include "optics/airy_kernel.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(AiryKernel, TruncatesAtTheChosenDarkRing) {
  const AiryKernel k(32);
  EXPECT_NEAR(std::cyl_bessel_j(1.0, k.max_radius()), 0.0, 1e-12);
  // McMahon: the k-th zero of J1 is near (k + 1/4) pi - 3 / (8 (k + 1/4) pi).
  const double b = (32 + 0.25) * std::numbers::pi;
  EXPECT_NEAR(k.max_radius(), b - 3.0 / (8.0 * b), 1e-4);
  EXPECT_NEAR(AiryKernel(1).max_radius(), 3.831705970207512, 1e-9);
  EXPECT_THROW(AiryKernel(0), OpticsError);
}

TEST(AiryKernel, EnergyIsRayleighs) {
  EXPECT_NEAR(AiryKernel::energy_within(3.831705970207512), 0.8378, 1e-4);  // the first dark ring
  // Rayleigh's formula is the integral of the intensity over the plane / 4 pi: check by quadrature.
  double integral = 0.0;
  const double h = 1e-3;
  for (double v = 0.5 * h; v < 10.0; v += h) integral += AiryKernel::intensity(v) * 2.0 * std::numbers::pi * v * h;
  EXPECT_NEAR(integral / (4.0 * std::numbers::pi), AiryKernel::energy_within(10.0), 1e-6);
}

TEST(AiryKernel, DensityIntegratesToOneAndMatchesTheIntensity) {
  const AiryKernel k;
  double integral = 0.0;
  const double h = 1e-3;
  for (double v = 0.5 * h; v < k.max_radius() + 1.0; v += h) integral += k.density(v) * 2.0 * std::numbers::pi * v * h;
  EXPECT_NEAR(integral, 1.0, 1e-4);
  for (double v : {0.0, 0.7, 1.6, 3.0, 5.2, 40.3})
    EXPECT_NEAR(k.density(v) * 4.0 * std::numbers::pi * AiryKernel::energy_within(k.max_radius()),
                AiryKernel::intensity(v), 2e-5)
        << v;
  EXPECT_EQ(k.density(k.max_radius() + 0.1), 0.0);
  EXPECT_EQ(k.density(-1.0), 0.0);
}

// Kolmogorov-Smirnov: with n = 200000 samples the statistic exceeds 1.95 / sqrt(n) with
// probability 0.001 if the samples follow the CDF.
TEST(AiryKernel, SamplerFollowsTheTruncatedCdf) {
  const AiryKernel k;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 200000;
  std::vector<double> v(n);
  for (double& x : v) x = k.sample_radius(u(rng));
  std::sort(v.begin(), v.end());
  double d = 0.0;
  for (int i = 0; i < n; ++i) {
    const double f = k.cdf(v[size_t(i)]);
    d = std::max({d, std::abs(f - double(i) / n), std::abs(f - double(i + 1) / n)});
  }
  EXPECT_LT(d, 1.95 / std::sqrt(double(n)));
  EXPECT_LE(v.back(), k.max_radius());
  // The median against Rayleigh's 50 % radius of the truncated pattern (bisection on the closed
  // form; about 1.68 = pi 0.535, the 0.535 lambda N of docs/wavefront.md).
  const double half = 0.5 * AiryKernel::energy_within(k.max_radius());
  double lo = 0.0, hi = 3.0;
  for (int i = 0; i < 60; ++i) (AiryKernel::energy_within(0.5 * (lo + hi)) < half ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NEAR(v[n / 2], 0.5 * (lo + hi), 0.01);
  EXPECT_NEAR(0.5 * (lo + hi), 1.68, 0.01);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
