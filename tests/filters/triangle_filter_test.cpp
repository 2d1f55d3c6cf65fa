// The triangle filter: weight 1, sample positions distributed as f / integral f (chi-square
// against the tent integrated per cell), the analytic integral r_x^2 r_y^2, pbrt-v4 defaults.
#include "filters/triangle_filter.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "../support/chi2.h"
#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

double tent(double x, double r) { return std::max(0.0, r - std::abs(x)); }

TEST(TriangleFilter, SamplesFollowTheTent) {
  for (Vec2 r : {Vec2(2.f), Vec2(1.f, 0.5f)}) {
    TriangleFilter f(r);
    chi2::Grid2D grid(32, 32, -r.x, r.x, -r.y, r.y);
    std::mt19937_64 rng(2);
    const int n = 500000;
    for (int i = 0; i < n; ++i) {
      Vec2 u(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f);
      FilterSample s = f.sample(u);
      ASSERT_EQ(s.weight, 1.f);
      grid.add(s.offset.x, s.offset.y);
    }
    EXPECT_EQ(grid.outside, 0u);
    // The density from a formula written here, not from evaluate().
    double integral = double(r.x) * r.x * r.y * r.y;
    auto expected = chi2::expected_per_cell(
        grid, [&](double x, double y) { return tent(x, r.x) * tent(y, r.y) / integral; }, n);
    chi2::Result res = chi2::pearson(grid.counts, expected);
    EXPECT_TRUE(res.passes(1e-4)) << res.summary();
  }
}

TEST(TriangleFilter, EvaluateAndIntegralMatchTheTent) {
  TriangleFilter f(Vec2(2.f, 1.f));
  for (Vec2 p : {Vec2(0.f), Vec2(1.f, 0.5f), Vec2(-1.5f, 0.25f), Vec2(2.5f, 0.f)})
    EXPECT_FLOAT_EQ(f.evaluate(p), float(tent(p.x, 2.0) * tent(p.y, 1.0)));
  double numeric = chi2::integrate_rect(
      [&](double x, double y) { return double(f.evaluate(Vec2(float(x), float(y)))); }, -2.0, 2.0, -1.0, 1.0, 16);
  EXPECT_NEAR(numeric, 4.0, 1e-5);
  EXPECT_FLOAT_EQ(f.integral(), 4.f);
}

TEST(TriangleFilter, TentSampleInvertsTheCdf) {
  // CDF of the tent on [-r, r]: (x + r)^2 / (2 r^2) left of 0, 1 - (r - x)^2 / (2 r^2) right of it.
  const float r = 1.5f;
  for (float u : {0.f, 0.1f, 0.3f, 0.5f, 0.75f, 0.99f}) {
    double x = sample_tent(u, r);
    double cdf = x < 0 ? (x + r) * (x + r) / (2.0 * r * r) : 1.0 - (r - x) * (r - x) / (2.0 * r * r);
    EXPECT_NEAR(cdf, u, 1e-6) << u;
  }
}

TEST(TriangleFilter, FactoryUsesPbrtDefaults) {
  ParameterList none;
  auto f = create_triangle_filter(none);
  EXPECT_EQ(f->radius(), Vec2(2.f));
  ParameterList bad;
  Param p;
  p.type = "float";
  p.name = "yradius";
  p.numbers = {-2.0};
  bad.add(p);
  EXPECT_THROW(create_triangle_filter(bad), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
