// The Mitchell-Netravali filter against the published cubic: kernel values, the integral
// r_x r_y / 4 for any B and C, signed importance-sampling weights whose weighted histogram
// reproduces the filter (chi-square) with mean weight 1, and the parameters.
#include "filters/mitchell_filter.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/chi2.h"
#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

// Mitchell & Netravali 1988, eq. 8, on [-2, 2].
double cubic(double x, double b, double c) {
  x = std::abs(x);
  if (x < 1) return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
  if (x < 2)
    return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) / 6;
  return 0;
}

TEST(MitchellFilter, KernelMatchesPublishedCubic) {
  const double third = 1.0 / 3.0;
  MitchellFilter f(Vec2(2.f), float(third), float(third));
  EXPECT_NEAR(f.mitchell_1d(0.f), 8.0 / 9.0, 1e-6);   // (6 - 2B) / 6
  EXPECT_NEAR(f.mitchell_1d(1.f), 1.0 / 18.0, 1e-6);  // B / 6
  EXPECT_NEAR(f.mitchell_1d(2.f), 0.0, 1e-6);
  EXPECT_LT(f.mitchell_1d(1.5f), 0.f);  // the negative lobe
  for (float x : {0.f, 0.3f, 0.8f, 1.2f, 1.7f, 2.5f}) EXPECT_NEAR(f.mitchell_1d(x), cubic(x, third, third), 1e-6);
  // evaluate() scales the kernel to the radius: f(x, y) = k(2x / rx) k(2y / ry).
  MitchellFilter g(Vec2(1.f, 3.f), 0.5f, 0.25f);
  EXPECT_NEAR(g.evaluate(Vec2(0.25f, 1.f)), cubic(0.5, 0.5, 0.25) * cubic(2.0 / 3.0, 0.5, 0.25), 1e-6);
}

TEST(MitchellFilter, IntegratesToAQuarterOfTheRadiiProductForAnyBC) {
  for (auto [b, c] : {std::pair{1.f / 3.f, 1.f / 3.f}, std::pair{0.f, 0.5f}, std::pair{1.f, 0.f}}) {
    MitchellFilter f(Vec2(2.f, 1.5f), b, c);
    double numeric = chi2::integrate_rect(
        [&](double x, double y) { return double(f.evaluate(Vec2(float(x), float(y)))); }, -2.0, 2.0, -1.5, 1.5, 16);
    EXPECT_NEAR(numeric, 2.0 * 1.5 / 4.0, 1e-5) << b << " " << c;
  }
}

TEST(MitchellFilter, WeightedSamplesReproduceTheFilter) {
  const double b = 1.0 / 3.0, c = 1.0 / 3.0;
  for (Vec2 r : {Vec2(2.f), Vec2(1.f, 2.5f)}) {
    MitchellFilter f(r, float(b), float(c));
    double integral = double(r.x) * r.y / 4.0;
    chi2::Grid2D grid(32, 32, -r.x, r.x, -r.y, r.y);
    std::mt19937_64 rng(4);
    const int n = 500000;
    double sum = 0, sum_sq = 0;
    int negative = 0;
    for (int i = 0; i < n; ++i) {
      Vec2 u(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f);
      FilterSample s = f.sample(u);
      ASSERT_TRUE(std::isfinite(s.weight));
      negative += s.weight < 0.f;
      grid.add(s.offset.x, s.offset.y, s.weight);
      sum += s.weight;
      sum_sq += double(s.weight) * s.weight;
    }
    EXPECT_EQ(grid.outside, 0u);
    EXPECT_GT(negative, n / 100);  // the lobes are sampled, with negative weights
    auto expected = chi2::expected_per_cell(
        grid, [&](double x, double y) { return cubic(2 * x / r.x, b, c) * cubic(2 * y / r.y, b, c) / integral; }, n);
    chi2::Result res = chi2::weighted_pearson(grid.weight_sums, grid.weight_sq_sums, grid.counts, expected);
    EXPECT_TRUE(res.passes(1e-4)) << res.summary();
    double mean = sum / n, sd = std::sqrt(std::max(0.0, sum_sq / n - mean * mean));
    EXPECT_NEAR(mean, 1.0, 4.4 * sd / std::sqrt(double(n)));  // two-sided, 1e-5
  }
}

TEST(MitchellFilter, FactoryUsesPbrtDefaults) {
  ParameterList none;
  auto f = create_mitchell_filter(none);
  EXPECT_EQ(f->radius(), Vec2(2.f));
  EXPECT_NE(f->to_string().find("B=0.33333334 C=0.33333334"), std::string::npos) << f->to_string();
  ParameterList bad;
  Param p;
  p.type = "float";
  p.name = "xradius";
  p.numbers = {0.0};
  bad.add(p);
  EXPECT_THROW(create_mitchell_filter(bad), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
