// The Gaussian filter against pbrt-v4's formula written out here: values, the analytic integral,
// importance-sampled weights whose weighted histogram reproduces the filter (chi-square) with
// mean weight 1, and the parameter checks.
#include "filters/gaussian_filter.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "../support/chi2.h"
#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

// pbrt-v4: max(0, G(x) - G(r)) with G the normal density of standard deviation sigma.
double shifted_gaussian(double x, double r, double sigma) {
  auto g = [&](double t) {
    return std::exp(-t * t / (2 * sigma * sigma)) / std::sqrt(2 * std::numbers::pi * sigma * sigma);
  };
  return std::max(0.0, g(x) - g(r));
}

double shifted_gaussian_integral(double r, double sigma) {
  double g_r = std::exp(-r * r / (2 * sigma * sigma)) / std::sqrt(2 * std::numbers::pi * sigma * sigma);
  return std::erf(r / (sigma * std::sqrt(2.0))) - 2 * r * g_r;
}

ParameterList float_params(std::vector<std::pair<const char*, double>> values) {
  ParameterList params;
  for (auto [name, v] : values) {
    Param p;
    p.type = "float";
    p.name = name;
    p.numbers = {v};
    params.add(p);
  }
  return params;
}

TEST(GaussianFilter, EvaluateMatchesPbrtFormula) {
  for (auto [r, sigma] : {std::pair{1.5f, 0.5f}, std::pair{3.f, 1.f}, std::pair{0.5f, 2.f}}) {
    GaussianFilter f(Vec2(r), sigma);
    for (Vec2 p :
         {Vec2(0.f), Vec2(0.3f, -0.2f), Vec2(0.49f, 0.1f), Vec2(r * 0.99f, 0.f), Vec2(r, 0.f), Vec2(r + 1.f, 0.f)}) {
      double expected = shifted_gaussian(p.x, r, sigma) * shifted_gaussian(p.y, r, sigma);
      EXPECT_NEAR(f.evaluate(p), expected, 1e-6 * std::max(1.0, expected)) << r << " " << sigma;
    }
  }
}

TEST(GaussianFilter, IntegralIsAnalytic) {
  GaussianFilter f(Vec2(1.5f, 1.f), 0.5f);
  double analytic = shifted_gaussian_integral(1.5, 0.5) * shifted_gaussian_integral(1.0, 0.5);
  double numeric = chi2::integrate_rect(
      [&](double x, double y) { return double(f.evaluate(Vec2(float(x), float(y)))); }, -1.5, 1.5, -1.0, 1.0, 64);
  EXPECT_NEAR(numeric / analytic, 1.0, 1e-5);
  EXPECT_NEAR(f.integral() / analytic, 1.0, 1e-6);
}

TEST(GaussianFilter, WeightedSamplesReproduceTheFilter) {
  for (auto [r, sigma] : {std::pair{Vec2(1.5f), 0.5f}, std::pair{Vec2(2.f, 1.f), 0.25f}}) {
    GaussianFilter f(r, sigma);
    double integral = shifted_gaussian_integral(r.x, sigma) * shifted_gaussian_integral(r.y, sigma);
    chi2::Grid2D grid(32, 32, -r.x, r.x, -r.y, r.y);
    std::mt19937_64 rng(3);
    const int n = 500000;
    double sum = 0, sum_sq = 0;
    for (int i = 0; i < n; ++i) {
      Vec2 u(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f);
      FilterSample s = f.sample(u);
      ASSERT_TRUE(std::isfinite(s.weight) && s.weight >= 0.f);
      grid.add(s.offset.x, s.offset.y, s.weight);
      sum += s.weight;
      sum_sq += double(s.weight) * s.weight;
    }
    EXPECT_EQ(grid.outside, 0u);
    // E[weight in a cell] = (integral of f over the cell) / (integral of f): weights average to 1.
    auto expected = chi2::expected_per_cell(
        grid,
        [&](double x, double y) {
          return shifted_gaussian(x, r.x, sigma) * shifted_gaussian(y, r.y, sigma) / integral;
        },
        n);
    chi2::Result res = chi2::weighted_pearson(grid.weight_sums, grid.weight_sq_sums, grid.counts, expected);
    EXPECT_TRUE(res.passes(1e-4)) << res.summary();
    double mean = sum / n, sd = std::sqrt(std::max(0.0, sum_sq / n - mean * mean));
    EXPECT_NEAR(mean, 1.0, 4.4 * sd / std::sqrt(double(n)) + 1e-9);  // two-sided, 1e-5
  }
}

TEST(GaussianFilter, WeightedTestRejectsAWrongShape) {
  // Samples of sigma = 0.5 judged against sigma = 0.55: the weighted chi-square must object.
  GaussianFilter f(Vec2(1.5f), 0.5f);
  double integral = shifted_gaussian_integral(1.5, 0.55) * shifted_gaussian_integral(1.5, 0.55);
  chi2::Grid2D grid(32, 32, -1.5, 1.5, -1.5, 1.5);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 500000; ++i) {
    FilterSample s = f.sample(Vec2(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f));
    grid.add(s.offset.x, s.offset.y, s.weight);
  }
  auto expected = chi2::expected_per_cell(
      grid,
      [&](double x, double y) { return shifted_gaussian(x, 1.5, 0.55) * shifted_gaussian(y, 1.5, 0.55) / integral; },
      500000);
  chi2::Result res = chi2::weighted_pearson(grid.weight_sums, grid.weight_sq_sums, grid.counts, expected);
  EXPECT_LT(res.p_value, 1e-6) << res.summary();
}

TEST(GaussianFilter, FactoryUsesPbrtDefaultsAndChecksSigma) {
  ParameterList none;
  auto f = create_gaussian_filter(none);
  EXPECT_EQ(f->radius(), Vec2(1.5f));
  EXPECT_NE(f->to_string().find("sigma=0.5"), std::string::npos) << f->to_string();
  for (double sigma : {0.0, -0.5, 1e-4}) {
    ParameterList bad = float_params({{"sigma", sigma}});
    EXPECT_THROW(create_gaussian_filter(bad), SceneError) << sigma;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
