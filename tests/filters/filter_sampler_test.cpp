// The piecewise-constant distributions behind filter importance sampling, against values worked
// out by hand and a chi-square test of the 2D distribution against its own table.
#include "filters/filter_sampler.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "../support/chi2.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;
using filter_sampling::Distribution1D;
using filter_sampling::Distribution2D;

TEST(FilterDistribution1D, InvertsTheCdfByHand) {
  // Values {1, 3, 0, 4} on [0, 2]: cells of width 0.5, integral 4, densities 1/4, 3/4, 0, 1;
  // the CDF reaches 1/8, 1/2, 1/2, 1 at the cell ends.
  Distribution1D d({1.f, 3.f, 0.f, 4.f}, 0.f, 2.f);
  EXPECT_FLOAT_EQ(d.integral(), 4.f);
  float pdf;
  int cell;
  EXPECT_FLOAT_EQ(d.sample(0.0625f, &pdf, &cell), 0.25f);
  EXPECT_EQ(cell, 0);
  EXPECT_FLOAT_EQ(pdf, 0.25f);
  EXPECT_FLOAT_EQ(d.sample(0.3125f, &pdf, &cell), 0.75f);
  EXPECT_FLOAT_EQ(pdf, 0.75f);
  // u = 1/2 is where cell 2 (empty) would start: it goes to cell 3 instead.
  EXPECT_FLOAT_EQ(d.sample(0.5f, &pdf, &cell), 1.5f);
  EXPECT_EQ(cell, 3);
  EXPECT_FLOAT_EQ(pdf, 1.f);
  float x = d.sample(0.99999994f, &pdf, &cell);
  EXPECT_TRUE(x <= 2.f && x > 1.99f);
}

TEST(FilterDistribution1D, AllZeroTableIsSampledUniformly) {
  Distribution1D d({0.f, 0.f}, -1.f, 1.f);
  float pdf;
  int cell;
  EXPECT_FLOAT_EQ(d.sample(0.75f, &pdf, &cell), 0.5f);
  EXPECT_FLOAT_EQ(pdf, 0.5f);
}

TEST(FilterDistribution2D, SamplesFollowTheTable) {
  const int nx = 6, ny = 5;
  std::vector<float> values(nx * ny);
  std::mt19937 rng(8);
  for (float& v : values) v = float(rng() % 10);
  values[7] = 0.f;
  Distribution2D d(values, nx, ny, Vec2(-1.f, 0.f), Vec2(2.f, 1.f));
  double total = 0;
  for (float v : values) total += v;
  double cell_area = 3.0 / nx * 1.0 / ny;
  EXPECT_NEAR(d.integral(), total * cell_area, 1e-4);
  chi2::Grid2D grid(nx, ny, -1.0, 2.0, 0.0, 1.0);
  std::mt19937_64 source(9);
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    Vec2 u(float(source() >> 40) * 0x1p-24f, float(source() >> 40) * 0x1p-24f);
    float pdf;
    Vec2 p = d.sample(u, &pdf);
    long c = grid.cell(p.x, p.y);
    ASSERT_GE(c, 0);
    ASSERT_NEAR(pdf, values[size_t(c)] / (total * cell_area), 1e-4);
    grid.add(p.x, p.y);
  }
  std::vector<double> expected(values.size());
  for (size_t i = 0; i < values.size(); ++i) expected[i] = n * values[i] / total;
  chi2::Result res = chi2::pearson(grid.counts, expected);
  EXPECT_TRUE(res.passes(1e-4)) << res.summary();
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
