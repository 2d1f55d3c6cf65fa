// The windowed sinc (Lanczos) filter against its closed form: values and zeros, the integral
// (an independent Gauss-Legendre quadrature, and the Fourier limit 1 for a wide window), signed
// importance-sampling weights whose weighted histogram reproduces the filter (chi-square) with
// mean weight 1, filter-weighted means of a function that are unbiased, and the parameters.
#include "filters/sinc_filter.h"
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

// sin(pi x) / (pi x) sin(pi x / tau) / (pi x / tau) for |x| <= r, written out here.
double lanczos(double x, double r, double tau) {
  if (std::abs(x) > r) return 0;
  if (x == 0) return 1;
  const double a = std::numbers::pi * x, b = a / tau;
  return std::sin(a) / a * std::sin(b) / b;
}

Vec2 uniform2(std::mt19937_64& rng) { return Vec2(float(rng() >> 40) * 0x1p-24f, float(rng() >> 40) * 0x1p-24f); }

TEST(SincFilter, ValuesMatchTheClosedForm) {
  SincFilter f(Vec2(4.f), 3.f);
  EXPECT_FLOAT_EQ(f.evaluate(Vec2(0.f)), 1.f);
  // The sinc's zeros at the integers, the window's at multiples of tau.
  for (float x : {1.f, 2.f, 3.f}) EXPECT_NEAR(f.evaluate(Vec2(x, 0.f)), 0.f, 1e-6f) << x;
  EXPECT_LT(f.evaluate(Vec2(1.5f, 0.f)), 0.f);  // the first negative lobe
  EXPECT_GT(f.evaluate(Vec2(3.5f, 0.f)), 0.f);  // beyond tau both factors are negative
  EXPECT_EQ(f.evaluate(Vec2(4.01f, 0.f)), 0.f);
  EXPECT_EQ(f.evaluate(Vec2(0.f, -4.01f)), 0.f);
  SincFilter g(Vec2(2.5f, 1.5f), 2.f);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200; ++i) {
    const Vec2 p = (2.f * uniform2(rng) - 1.f) * Vec2(2.6f, 1.6f);
    EXPECT_NEAR(g.evaluate(p), lanczos(p.x, 2.5, 2) * lanczos(p.y, 1.5, 2), 2e-6) << p.x << " " << p.y;
  }
  // Close to 0 the series branch joins the quotient smoothly.
  EXPECT_NEAR(SincFilter::sinc(0.9e-4 / std::numbers::pi), SincFilter::sinc(1.1e-4 / std::numbers::pi), 1e-8);
}

TEST(SincFilter, IntegralMatchesAnIndependentQuadratureAndTheFourierLimit) {
  for (auto [r, tau] : {std::pair{4.0, 3.0}, std::pair{2.0, 2.0}, std::pair{3.0, 1.5}}) {
    // 1D, Gauss-Legendre over 64 panels per unit (the integrand is smooth inside the radius).
    double numeric =
        chi2::integrate_rect([&](double x, double) { return lanczos(x, r, tau); }, -r, r, 0, 1, int(64 * r));
    EXPECT_NEAR(SincFilter::windowed_sinc_integral(r, tau), numeric, 1e-9) << r << " " << tau;
  }
  // The product of the two axes'.
  SincFilter f(Vec2(4.f, 2.f), 3.f);
  EXPECT_NEAR(f.integral(), SincFilter::windowed_sinc_integral(4, 3) * SincFilter::windowed_sinc_integral(2, 3), 1e-6);
  // With an unbounded radius the integral of sinc(x) sinc(x / tau) is 1 for tau >= 1 (Parseval:
  // the spectra are boxes of widths 1 and 1 / tau, heights 1 and tau). The tail beyond r is
  // bounded by tau / (pi^2 r).
  const double r = 400, tau = 3;
  EXPECT_NEAR(SincFilter::windowed_sinc_integral(r, tau), 1.0, tau / (std::numbers::pi * std::numbers::pi * r));
}

TEST(SincFilter, WeightedSamplesReproduceTheFilter) {
  for (auto [r, tau] : {std::pair{Vec2(4.f), 3.f}, std::pair{Vec2(2.f, 3.f), 2.f}}) {
    SincFilter f(r, tau);
    const double integral = f.integral();
    chi2::Grid2D grid(32, 32, -r.x, r.x, -r.y, r.y);
    std::mt19937_64 rng(4);
    const int n = 500000;
    double sum = 0, sum_sq = 0;
    int negative = 0;
    for (int i = 0; i < n; ++i) {
      FilterSample s = f.sample(uniform2(rng));
      ASSERT_TRUE(std::isfinite(s.weight));
      negative += s.weight < 0.f;
      grid.add(s.offset.x, s.offset.y, s.weight);
      sum += s.weight;
      sum_sq += double(s.weight) * s.weight;
    }
    EXPECT_EQ(grid.outside, 0u);
    EXPECT_GT(negative, n / 10);  // the lobes are sampled, with negative weights
    auto expected = chi2::expected_per_cell(
        grid, [&](double x, double y) { return lanczos(x, r.x, tau) * lanczos(y, r.y, tau) / integral; }, n);
    chi2::Result res = chi2::weighted_pearson(grid.weight_sums, grid.weight_sq_sums, grid.counts, expected);
    EXPECT_TRUE(res.passes(1e-4)) << res.summary();
    double mean = sum / n, sd = std::sqrt(std::max(0.0, sum_sq / n - mean * mean));
    EXPECT_NEAR(mean, 1.0, 4.4 * sd / std::sqrt(double(n)));  // two-sided, 1e-5
  }
}

// What a pixel estimates: sum w L / n over samples is the filter-weighted mean of L, the integral
// of f L over the integral of f (here by quadrature), for a radiance with an edge and a slope.
TEST(SincFilter, SampledWeightsGiveUnbiasedFilterWeightedMeans) {
  SincFilter f(Vec2(4.f), 3.f);
  auto radiance = [](double x, double y) { return (x > 0.7 ? 2.0 : 0.5) + 0.1 * y + 0.05 * x * y; };
  const double expected =
      chi2::integrate_rect([&](double x, double y) { return lanczos(x, 4, 3) * lanczos(y, 4, 3) * radiance(x, y); }, -4,
                           4, -4, 4, 160) /
      f.integral();
  std::mt19937_64 rng(11);
  const int n = 400000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    FilterSample s = f.sample(uniform2(rng));
    const double v = s.weight * radiance(s.offset.x, s.offset.y);
    sum += v;
    sum_sq += v * v;
  }
  const double mean = sum / n, sd = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(mean, expected, 4.4 * sd / std::sqrt(double(n))) << "sd " << sd;  // two-sided, 1e-5
  // The edge matters: the plain mean over the filter's square is far from it.
  EXPECT_GT(std::abs(expected - (2.0 * 3.3 + 0.5 * 4.7) / 8.0), 20 * sd / std::sqrt(double(n)));
}

Param float_param(const std::string& name, double v) {
  Param p;
  p.type = "float";
  p.name = name;
  p.numbers = {v};
  p.loc = SourceLoc{"scene.pbrt", 4, 13};
  return p;
}

TEST(SincFilter, FactoryUsesPbrtDefaultsAndRejectsBadValues) {
  ParameterList none;
  auto f = create_sinc_filter(none);
  EXPECT_EQ(f->radius(), Vec2(4.f));
  EXPECT_NE(f->to_string().find("tau=3"), std::string::npos) << f->to_string();
  for (auto [name, value] : {std::pair{"tau", 0.0}, std::pair{"xradius", 0.0}, std::pair{"yradius", -1.0}}) {
    ParameterList bad;
    bad.add(float_param(name, value));
    try {
      create_sinc_filter(bad);
      ADD_FAILURE() << name << " " << value << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("scene.pbrt:4:13"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
