// The Henyey-Greenstein phase function against its closed-form properties: it integrates to 1
// over the sphere, its mean cosine is g, and the sampler draws directions with exactly its
// density (a chi-square test of the cosine histogram against the analytic CDF).
#include "core/henyey_greenstein.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// CDF of cos theta under HG (the closed form of the integral of 2 pi p over [-1, c]).
double hg_cdf(double c, double g) {
  if (std::abs(g) < 1e-6) return 0.5 * (c + 1.0);
  const double k = (1 - g * g) / (2 * g);
  return k * (1.0 / std::sqrt(1 + g * g - 2 * g * c) - 1.0 / (1 + g));
}

TEST(HenyeyGreenstein, IntegratesToOneOverTheSphere) {
  for (float g : {-0.9f, -0.3f, 0.f, 0.5f, 0.95f}) {
    // Midpoint rule in cos theta with 200000 cells: the integrand is smooth (|g| < 1).
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += henyey_greenstein(float(-1.0 + (i + 0.5) * 2.0 / n), g);
    EXPECT_NEAR(sum * 2.0 / n * 2 * kPi, 1.0, 2e-3) << "g " << g;
  }
}

TEST(HenyeyGreenstein, SampledMeanCosineIsG) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  const Vec3 d = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));
  for (float g : {-0.7f, 0.f, 0.4f, 0.9f}) {
    const int n = 200000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 w = sample_henyey_greenstein(d, g, Vec2(u(rng), u(rng)));
      ASSERT_NEAR(glm::length(w), 1.f, 1e-4f);
      const double c = glm::dot(w, d);
      sum += c;
      sum2 += c * c;
    }
    const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, g, 5 * se + 1e-4) << "g " << g;  // 5 standard errors
  }
}

TEST(HenyeyGreenstein, SamplesFollowTheDensity) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  const Vec3 d(0.f, 0.f, 1.f);
  for (float g : {-0.5f, 0.3f, 0.8f}) {
    const int bins = 20, n = 100000;
    std::vector<int> count(bins, 0);
    for (int i = 0; i < n; ++i) {
      const float c = glm::dot(sample_henyey_greenstein(d, g, Vec2(u(rng), u(rng))), d);
      count[std::min(bins - 1, int((c + 1.f) * 0.5f * bins))]++;
    }
    double chi2 = 0;
    for (int b = 0; b < bins; ++b) {
      const double p = hg_cdf(-1.0 + 2.0 * (b + 1) / bins, g) - hg_cdf(-1.0 + 2.0 * b / bins, g);
      chi2 += (count[b] - n * p) * (count[b] - n * p) / (n * p);
    }
    // 19 degrees of freedom: P(chi2 > 43.8) = 0.001.
    EXPECT_LT(chi2, 43.8) << "g " << g;
  }
}

TEST(HenyeyGreenstein, ForwardScatteringFavoursTheTravelDirection) {
  EXPECT_GT(henyey_greenstein(1.f, 0.5f), henyey_greenstein(-1.f, 0.5f));
  // Closed form at theta = 0: (1 - g^2) / (4 pi (1 - g)^3) = (1 + g) / (4 pi (1 - g)^2).
  EXPECT_NEAR(henyey_greenstein(1.f, 0.5f), 1.5 / (4 * kPi * 0.25), 1e-5);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
