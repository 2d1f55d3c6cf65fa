// The box filter: constant weight 1, samples uniform over [-r, r]^2 (chi-square), pbrt-v4's
// default radius and parameter checks.
#include "filters/box_filter.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "../support/chi2.h"
#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

ParameterList radius_params(float rx, float ry) {
  ParameterList params;
  for (auto [name, v] : {std::pair{"xradius", rx}, std::pair{"yradius", ry}}) {
    Param p;
    p.type = "float";
    p.name = name;
    p.numbers = {double(v)};
    params.add(p);
  }
  return params;
}

TEST(BoxFilter, SamplesAreUniformWithWeightOne) {
  for (Vec2 r : {Vec2(0.5f), Vec2(1.5f, 0.75f)}) {
    BoxFilter f(r);
    chi2::Grid2D grid(20, 20, -r.x, r.x, -r.y, r.y);
    std::mt19937_64 rng(1);
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      Vec2 u(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f);
      FilterSample s = f.sample(u);
      ASSERT_EQ(s.weight, 1.f);
      ASSERT_EQ(f.evaluate(s.offset), 1.f);
      grid.add(s.offset.x, s.offset.y);
    }
    EXPECT_EQ(grid.outside, 0u);
    auto expected = chi2::expected_per_cell(
        grid, [&](double, double) { return 1.0 / (4.0 * r.x * r.y); }, n);
    chi2::Result res = chi2::pearson(grid.counts, expected);
    EXPECT_TRUE(res.passes(1e-4)) << res.summary();
  }
}

TEST(BoxFilter, EvaluatesToOneInsideAndZeroOutside) {
  BoxFilter f(Vec2(0.5f, 1.f));
  EXPECT_EQ(f.evaluate(Vec2(0.f)), 1.f);
  EXPECT_EQ(f.evaluate(Vec2(0.5f, -1.f)), 1.f);
  EXPECT_EQ(f.evaluate(Vec2(0.51f, 0.f)), 0.f);
  EXPECT_EQ(f.evaluate(Vec2(0.f, 1.01f)), 0.f);
  EXPECT_FLOAT_EQ(f.integral(), 2.f);
  // The corners of the unit square map to the corners of the box.
  EXPECT_EQ(f.sample(Vec2(0.f)).offset, Vec2(-0.5f, -1.f));
}

TEST(BoxFilter, FactoryUsesPbrtDefaultsAndChecksRadius) {
  ParameterList none;
  auto f = create_box_filter(none);
  EXPECT_EQ(f->radius(), Vec2(0.5f));
  EXPECT_NE(f->to_string().find("xradius=0.5"), std::string::npos) << f->to_string();
  ParameterList custom = radius_params(1.f, 2.f);
  EXPECT_EQ(create_box_filter(custom)->radius(), Vec2(1.f, 2.f));
  for (float bad : {0.f, -1.f, 1000.f}) {
    ParameterList params = radius_params(bad, 0.5f);
    EXPECT_THROW(create_box_filter(params), SceneError) << bad;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
