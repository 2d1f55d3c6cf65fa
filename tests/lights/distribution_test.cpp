// PiecewiseConstant1D/2D: sampling follows the function (chi-square, 1% significance),
// densities are the function over its integral (computed here independently), invert()
// undoes sample(), and degenerate (all-zero, negative, NaN) input never yields NaN.
#include <gtest/gtest.h>

#include <numeric>

#include "../support/unity_id.h"
#include "core/distribution.h"
#include "light_test_util.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kSignificance = 0.01;

TEST(PiecewiseConstant1D, SamplingMatchesFunctionChiSquare) {
  std::vector<float> f = {1.f, 0.f, 3.f, 2.f, 0.5f, 0.f, 4.f, 0.25f};
  PiecewiseConstant1D d(f);
  double sum = std::accumulate(f.begin(), f.end(), 0.0);
  const int n = 200000;
  std::vector<double> observed(f.size(), 0.0), expected(f.size());
  for (size_t i = 0; i < f.size(); ++i) expected[i] = n * f[i] / sum;
  Uniform rng(7);
  for (int k = 0; k < n; ++k) {
    float pdf = 0.f;
    int offset = -1;
    float x = d.sample(rng.next(), &pdf, &offset);
    ASSERT_GE(x, 0.f);
    ASSERT_LT(x, 1.f);
    ASSERT_EQ(int(x * f.size()), offset);  // the continuous sample lies in its bin
    observed[offset] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_EQ(r.impossible, 0);
  EXPECT_GT(r.p_value, kSignificance) << "chi2 = " << r.statistic << " dof = " << r.dof;
}

TEST(PiecewiseConstant1D, DensityIsFunctionOverIntegral) {
  std::vector<float> f = {2.f, 6.f, 0.f, 8.f};
  PiecewiseConstant1D d(f);
  double integral = (2.0 + 6.0 + 0.0 + 8.0) / 4.0;  // each bin has width 1/4
  EXPECT_NEAR(d.integral(), integral, 1e-6);
  EXPECT_EQ(d.size(), 4u);
  Uniform rng(3);
  for (int k = 0; k < 1000; ++k) {
    float pdf = 0.f;
    int o = 0;
    float x = d.sample(rng.next(), &pdf, &o);
    EXPECT_NEAR(pdf, f[o] / integral, 1e-5);
    EXPECT_NEAR(d.pdf(x), f[o] / integral, 1e-5);
  }
  EXPECT_NEAR(d.pmf(1), 6.0 / 16.0, 1e-7);
  EXPECT_EQ(d.pmf(2), 0.f);
  EXPECT_EQ(d.pmf(7), 0.f);  // out of range
}

TEST(PiecewiseConstant1D, InvertUndoesSample) {
  std::vector<float> f = {0.1f, 5.f, 0.f, 2.f, 3.f, 0.7f};
  PiecewiseConstant1D d(f);
  for (int k = 0; k < 1000; ++k) {
    float u = (k + 0.5f) / 1000.f;
    std::optional<float> back = d.invert(d.sample(u));
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(*back, u, 2e-6f);
  }
  EXPECT_FALSE(d.invert(-0.1f).has_value());
  EXPECT_FALSE(d.invert(1.5f).has_value());
}

TEST(PiecewiseConstant1D, DiscreteSamplingMatchesPmfChiSquare) {
  std::vector<float> f = {10.f, 1.f, 0.f, 5.f, 20.f};
  PiecewiseConstant1D d(f);
  double sum = 36.0;
  const int n = 100000;
  std::vector<double> observed(f.size(), 0.0), expected(f.size());
  for (size_t i = 0; i < f.size(); ++i) expected[i] = n * f[i] / sum;
  Uniform rng(11);
  double pmf_total = 0.0;
  for (size_t i = 0; i < f.size(); ++i) pmf_total += d.pmf(i);
  EXPECT_NEAR(pmf_total, 1.0, 1e-6);
  for (int k = 0; k < n; ++k) {
    float pmf = 0.f;
    size_t i = d.sample_discrete(rng.next(), &pmf);
    ASSERT_NEAR(pmf, f[i] / sum, 1e-6);
    observed[i] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_EQ(r.impossible, 0);
  EXPECT_GT(r.p_value, kSignificance);
}

TEST(PiecewiseConstant1D, AllZeroIsUniformWithoutNaN) {
  std::vector<float> f(5, 0.f);
  PiecewiseConstant1D d(f);
  EXPECT_EQ(d.integral(), 0.f);
  for (float u : {0.f, 0.1f, 0.5f, 0.77f, kOneMinusEpsilon}) {
    float pdf = -1.f;
    float x = d.sample(u, &pdf);
    EXPECT_NEAR(x, u, 1e-6f);  // the identity map: uniform
    EXPECT_EQ(pdf, 1.f);
    float pmf = -1.f;
    d.sample_discrete(u, &pmf);
    EXPECT_FLOAT_EQ(pmf, 0.2f);
  }
  EXPECT_FLOAT_EQ(d.pmf(3), 0.2f);
  EXPECT_EQ(d.pdf(0.3f), 1.f);
  PiecewiseConstant1D empty{std::vector<float>{}};
  float pdf = -1.f;
  EXPECT_TRUE(std::isfinite(empty.sample(0.4f, &pdf)));
  EXPECT_EQ(pdf, 1.f);
}

TEST(PiecewiseConstant1D, NegativeAndNonFiniteValuesCountAsZero) {
  std::vector<float> f = {-3.f, 2.f, std::nanf(""), kInfinity, 2.f};
  PiecewiseConstant1D d(f);
  EXPECT_FLOAT_EQ(d.pmf(0), 0.f);
  EXPECT_FLOAT_EQ(d.pmf(2), 0.f);
  EXPECT_FLOAT_EQ(d.pmf(3), 0.f);
  EXPECT_FLOAT_EQ(d.pmf(1), 0.5f);
  EXPECT_FLOAT_EQ(d.integral(), 4.f / 5.f);
}

// A 4 x 3 function with a zero row and zero cells.
std::vector<float> test_function_2d() {
  return {1.f, 2.f,  0.f, 4.f,  //
          0.f, 0.f,  0.f, 0.f,  //
          3.f, 0.5f, 6.f, 1.f};
}

TEST(PiecewiseConstant2D, SamplingMatchesFunctionChiSquare) {
  std::vector<float> f = test_function_2d();
  PiecewiseConstant2D d(f, 4, 3);
  double sum = std::accumulate(f.begin(), f.end(), 0.0);
  double integral = sum / 12.0;
  EXPECT_NEAR(d.integral(), integral, 1e-6);
  const int n = 200000;
  std::vector<double> observed(f.size(), 0.0), expected(f.size());
  for (size_t i = 0; i < f.size(); ++i) expected[i] = n * f[i] / sum;
  Uniform rng(5);
  for (int k = 0; k < n; ++k) {
    float pdf = 0.f;
    IVec2 cell;
    Vec2 p = d.sample(rng.next2(), &pdf, &cell);
    ASSERT_EQ(int(p.x * 4), cell.x);
    ASSERT_EQ(int(p.y * 3), cell.y);
    size_t i = size_t(cell.y) * 4 + cell.x;
    ASSERT_NEAR(pdf, f[i] / integral, 1e-4);
    ASSERT_NEAR(d.pdf(p), pdf, 1e-5);
    observed[i] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_EQ(r.impossible, 0);
  EXPECT_GT(r.p_value, kSignificance);
}

TEST(PiecewiseConstant2D, PdfIntegratesToOne) {
  std::vector<float> f = test_function_2d();
  PiecewiseConstant2D d(f, 4, 3);
  const int m = 240;  // a multiple of 4 and 3: cell midpoints never straddle a step
  double total = 0.0;
  for (int y = 0; y < m; ++y)
    for (int x = 0; x < m; ++x) total += d.pdf(Vec2((x + 0.5f) / m, (y + 0.5f) / m));
  EXPECT_NEAR(total / (m * m), 1.0, 1e-5);
}

TEST(PiecewiseConstant2D, InvertUndoesSample) {
  std::vector<float> f = test_function_2d();
  PiecewiseConstant2D d(f, 4, 3);
  Uniform rng(9);
  for (int k = 0; k < 1000; ++k) {
    Vec2 u = rng.next2();
    std::optional<Vec2> back = d.invert(d.sample(u));
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->x, u.x, 1e-5f);
    EXPECT_NEAR(back->y, u.y, 1e-5f);
  }
}

TEST(PiecewiseConstant2D, AllZeroIsUniformWithoutNaN) {
  std::vector<float> f(6, 0.f);
  PiecewiseConstant2D d(f, 3, 2);
  float pdf = -1.f;
  Vec2 p = d.sample(Vec2(0.3f, 0.8f), &pdf);
  EXPECT_NEAR(p.x, 0.3f, 1e-6f);
  EXPECT_NEAR(p.y, 0.8f, 1e-6f);
  EXPECT_EQ(pdf, 1.f);
  EXPECT_EQ(d.pdf(Vec2(0.9f, 0.1f)), 1.f);
}

TEST(PiecewiseConstant2D, SizeMismatchThrows) {
  std::vector<float> f(5, 1.f);
  EXPECT_THROW(PiecewiseConstant2D(f, 2, 3), std::invalid_argument);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
