// Chi-square tests of every warp in core/sampling.h against the density it states, and tests
// of the chi-square harness itself (tests/support/chi2.h) against published values.
#include "core/sampling.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/chi2.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

constexpr int kSamples = 1'000'000;
// Family-wise significance 1e-3 over the warp tests of this file (Bonferroni).
constexpr int kWarpTests = 10;
constexpr double kSignificance = 1e-3 / kWarpTests;
constexpr double kTwoPi = kTwoPiDouble;

// Uniform points from a generator independent of the renderer: 24-bit floats in [0, 1).
class UniformSource {
 public:
  explicit UniformSource(uint64_t seed) : rng_(seed) {}
  Vec2 next() {
    float x = float(rng_() >> 40) * 0x1p-24f;
    float y = float(rng_() >> 40) * 0x1p-24f;
    return Vec2(x, y);
  }

 private:
  std::mt19937_64 rng_;
};

double azimuth(double x, double y) {
  double phi = std::atan2(y, x);
  return phi < 0.0 ? phi + kTwoPi : phi;
}

// Directions binned by (z, phi): there the solid angle is dz dphi, so the expected count of a
// cell is N times the integral of the solid-angle density over it.
template <typename Warp, typename Pdf>
chi2::Result direction_test(Warp warp, Pdf pdf, double z_lo, double z_hi, uint64_t seed) {
  chi2::Grid2D grid(40, 80, z_lo, z_hi, 0.0, kTwoPi);
  UniformSource source(seed);
  for (int i = 0; i < kSamples; ++i) {
    Vec3 w = warp(source.next());
    grid.add(w.z, azimuth(w.x, w.y));
  }
  EXPECT_EQ(grid.outside, 0u);
  auto expected = chi2::expected_per_cell(
      grid, [&](double z, double) { return pdf(z); }, kSamples);
  double total = 0.0;
  for (double e : expected) total += e;
  EXPECT_NEAR(total / kSamples, 1.0, 1e-4) << "the stated density does not integrate to 1";
  return chi2::pearson(grid.counts, expected);
}

// Points of the unit disk binned by (r, phi): the area element is r dr dphi.
template <typename Warp>
chi2::Result disk_test(Warp warp, uint64_t seed) {
  chi2::Grid2D grid(40, 80, 0.0, 1.0, 0.0, kTwoPi);
  UniformSource source(seed);
  for (int i = 0; i < kSamples; ++i) {
    Vec2 p = warp(source.next());
    grid.add(std::hypot(double(p.x), double(p.y)), azimuth(p.x, p.y));
  }
  EXPECT_EQ(grid.outside, 0u);
  auto expected = chi2::expected_per_cell(
      grid, [](double r, double) { return r / kPi; }, kSamples);
  return chi2::pearson(grid.counts, expected);
}

// --- The harness ---

TEST(Chi2Harness, SurvivalMatchesPublishedCriticalValues) {
  // Upper 5% and 0.1% points of the chi-square distribution (NIST/SEMATECH e-Handbook, 1.3.6.7.4).
  EXPECT_NEAR(chi2::survival(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(chi2::survival(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(chi2::survival(124.342, 100), 0.05, 1e-4);
  EXPECT_NEAR(chi2::survival(10.828, 1), 0.001, 1e-5);
  EXPECT_NEAR(chi2::survival(149.449, 100), 0.001, 1e-5);
  // Two degrees of freedom: exactly exp(-x / 2).
  for (double x : {0.1, 1.0, 7.5, 60.0}) EXPECT_NEAR(chi2::survival(x, 2) / std::exp(-x / 2), 1.0, 1e-12);
}

TEST(Chi2Harness, PearsonPoolsLowExpectedCellsAsComputedByHand) {
  // Sorted by expected count: 0.5, 0.5 and then 15 join the pool (its expectation 1 is still
  // below 5 when the 15 arrives), leaving terms (20-15)^2/15, (30-30)^2/30 and (11-16)^2/16.
  chi2::Result r = chi2::pearson({10, 20, 30, 1, 0}, {15, 15, 30, 0.5, 0.5});
  ASSERT_TRUE(r.error.empty());
  EXPECT_EQ(r.pooled_cells, 3);
  EXPECT_EQ(r.dof, 2);
  EXPECT_NEAR(r.statistic, 25.0 / 15.0 + 25.0 / 16.0, 1e-12);
  EXPECT_NEAR(r.p_value, std::exp(-r.statistic / 2), 1e-12);
}

TEST(Chi2Harness, RejectsAWrongDensity) {
  // Cosine-weighted directions tested against the uniform hemisphere density must fail.
  chi2::Result r = direction_test(
      sample_cosine_hemisphere, [](double) { return double(uniform_hemisphere_pdf()); }, 0.0, 1.0, 11);
  EXPECT_LT(r.p_value, 1e-12) << r.summary();
}

TEST(Chi2Harness, ReportsSamplesWhereTheDensityIsZero) {
  chi2::Result r = direction_test(
      sample_uniform_sphere, [](double z) { return z > 0 ? double(uniform_hemisphere_pdf()) : 0.0; }, -1.0, 1.0, 12);
  EXPECT_FALSE(r.error.empty());
  EXPECT_FALSE(r.passes(kSignificance));
}

// --- The warps ---

TEST(SamplingWarps, ConcentricDiskIsUniform) {
  chi2::Result r = disk_test(sample_uniform_disk_concentric, 1);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, PolarDiskIsUniform) {
  chi2::Result r = disk_test(sample_uniform_disk_polar, 2);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, CosineHemisphereFollowsItsPdf) {
  // Over the whole sphere, so that any direction below the horizon is caught.
  chi2::Result r = direction_test(
      sample_cosine_hemisphere, [](double z) { return z > 0 ? double(cosine_hemisphere_pdf(float(z))) : 0.0; }, -1.0,
      1.0, 3);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, UniformSphereFollowsItsPdf) {
  chi2::Result r = direction_test(
      sample_uniform_sphere, [](double) { return double(uniform_sphere_pdf()); }, -1.0, 1.0, 4);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, UniformHemisphereFollowsItsPdf) {
  chi2::Result r = direction_test(
      sample_uniform_hemisphere, [](double z) { return z > 0 ? double(uniform_hemisphere_pdf()) : 0.0; }, -1.0, 1.0, 5);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, UniformConeFollowsItsPdf) {
  uint64_t seed = 6;
  for (float cos_max : {-0.5f, 0.3f, 0.9f, 0.999f}) {
    // The grid spans the cone; a direction outside it would be counted as outside the grid.
    chi2::Result r = direction_test([&](Vec2 u) { return sample_uniform_cone(u, cos_max); },
                                    [&](double) { return double(uniform_cone_pdf(cos_max)); }, cos_max, 1.0, seed++);
    EXPECT_TRUE(r.passes(kSignificance)) << "cos_max " << cos_max << ": " << r.summary();
  }
}

TEST(SamplingWarps, UniformTriangleBarycentricsAreUniform) {
  // (b0, b1) uniform on the triangle has density 2; binned by (a, c) = (b0 + b1, b0 / (b0 + b1))
  // the density is 2a on the unit square, smooth, so cells never straddle the diagonal edge.
  chi2::Grid2D grid(50, 50, 0.0, 1.0, 0.0, 1.0);
  UniformSource source(10);
  for (int i = 0; i < kSamples; ++i) {
    Vec2 b = sample_uniform_triangle(source.next());
    ASSERT_TRUE(b.x >= 0.f && b.y >= 0.f && b.x + b.y <= 1.f + 1e-6f);
    double a = double(b.x) + double(b.y);
    grid.add(a, a > 0.0 ? double(b.x) / a : 0.0);
  }
  EXPECT_EQ(grid.outside, 0u);
  auto expected = chi2::expected_per_cell(
      grid, [](double a, double) { return 2.0 * a; }, kSamples);
  chi2::Result r = chi2::pearson(grid.counts, expected);
  EXPECT_TRUE(r.passes(kSignificance)) << r.summary();
}

TEST(SamplingWarps, ConcentricDiskMapsTheSquareCentreToTheOrigin) {
  EXPECT_EQ(sample_uniform_disk_concentric(Vec2(0.5f)), Vec2(0.f));
  // The square's edges map to the circle (the map preserves the boundary).
  for (Vec2 u : {Vec2(0.f, 0.3f), Vec2(1.f, 0.7f), Vec2(0.2f, 1.f), Vec2(0.9f, 0.f)})
    EXPECT_NEAR(glm::length(sample_uniform_disk_concentric(u)), 1.f, 1e-6f);
}

TEST(PowerHeuristic, WeightsOfTwoStrategiesSumToOne) {
  for (float f : {0.1f, 1.f, 7.f})
    for (float g : {0.f, 0.5f, 3.f}) EXPECT_NEAR(power_heuristic(f, g) + power_heuristic(g, f), 1.f, 1e-6f);
  EXPECT_FLOAT_EQ(power_heuristic(2.f, 1.f), 0.8f);  // 4 / (4 + 1)
  EXPECT_EQ(power_heuristic(kInfinity, 1.f), 1.f);
  EXPECT_EQ(power_heuristic(0.f, 0.f), 0.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
