// The dispersive eye splats a wavelength with the pixel filter's weights as the product of two
// one-dimensional factors, f(x, y) = f(x, 0) f(0, y) / f(0, 0) (Filter::evaluate_axis,
// core/wavelength_splat.h): every filter must be such a product, as pbrt-v4's are by definition (each is written as a
// product of one-dimensional functions of x and y). Checked at random points of each filter's support, including the
// negative lobes of Mitchell and the windowed sinc.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "../support/unity_id.h"
#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "filters/mitchell_filter.h"
#include "filters/sinc_filter.h"
#include "filters/triangle_filter.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::vector<std::unique_ptr<Filter>> every_filter() {
  std::vector<std::unique_ptr<Filter>> filters;
  filters.push_back(std::make_unique<BoxFilter>(Vec2(0.5f, 0.7f)));
  filters.push_back(std::make_unique<TriangleFilter>(Vec2(2.f, 1.5f)));
  filters.push_back(std::make_unique<GaussianFilter>(Vec2(1.5f, 2.f), 0.5f));
  filters.push_back(std::make_unique<MitchellFilter>(Vec2(2.f, 2.f), 1.f / 3.f, 1.f / 3.f));
  filters.push_back(std::make_unique<SincFilter>(Vec2(4.f, 3.f), 3.f));
  return filters;
}

TEST(SeparableFilters, EveryFilterIsAProductOfItsAxes) {
  const std::vector<std::unique_ptr<Filter>> filters = every_filter();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (const auto& f : filters) {
    const Vec2 r = f->radius();
    const float centre = f->evaluate(Vec2(0.f));
    ASSERT_NE(centre, 0.f) << f->to_string();
    float largest = 0.f;
    for (int i = 0; i < 2000; ++i) largest = std::max(largest, std::abs(f->evaluate(Vec2(u(rng) * r.x, u(rng) * r.y))));
    for (int i = 0; i < 2000; ++i) {
      const Vec2 p(u(rng) * r.x, u(rng) * r.y);
      const float product = f->evaluate(Vec2(p.x, 0.f)) * f->evaluate(Vec2(0.f, p.y)) / centre;
      EXPECT_NEAR(f->evaluate(p), product, 1e-5f * largest) << f->to_string() << " at " << p.x << ", " << p.y;
      // And the factors the splats use (Filter::evaluate_axis).
      EXPECT_NEAR(f->evaluate(p), f->evaluate_axis(p.x, 0) * f->evaluate_axis(p.y, 1), 1e-5f * largest)
          << f->to_string() << " at " << p.x << ", " << p.y;
    }
  }
}

// A splat's row of factors (Filter::evaluate_axis_row: the Gaussian's from a piecewise-cubic
// table) is the factors one by one, over rows starting anywhere from beyond the support's left
// end to past its right, for every filter and the narrowest Gaussian (its table the largest).
TEST(SeparableFilters, RowsOfFactorsAreTheFactors) {
  std::vector<std::unique_ptr<Filter>> filters = every_filter();
  filters.push_back(std::make_unique<GaussianFilter>(Vec2(1.5f, 1.5f), GaussianFilter::min_sigma(Vec2(1.5f))));
  filters.push_back(std::make_unique<GaussianFilter>(Vec2(3.5f, 0.5f), 2.f));
  std::mt19937 rng(3);
  for (const auto& f : filters)
    for (int axis = 0; axis < 2; ++axis) {
      const float r = f->radius()[axis], centre = f->evaluate_axis(0.f, axis);
      std::uniform_real_distribution<double> start(-r - 1.0, 2.0 * r + 2.0);
      for (int i = 0; i < 2000; ++i) {
        const double t0 = start(rng);
        const int n = 1 + i % 8;
        float row[8];
        f->evaluate_axis_row(t0, n, axis, row);
        for (int k = 0; k < n; ++k)
          ASSERT_NEAR(row[k], f->evaluate_axis(float(t0 - k), axis), 2e-6f * std::abs(centre))
              << f->to_string() << " axis " << axis << " row from " << t0 << ", tap " << k;
      }
    }
}

// Filter::integral (which normalises the samples' weights and bdpt's light splats) is each
// filter's signed integral over its support: against the midpoint rule on a 512 x 512 grid
// (exact for the box and the triangle, within 1e-4 of the smooth filters' integrals).
TEST(SeparableFilters, IntegralIsTheIntegralOfEvaluate) {
  for (const auto& f : every_filter()) {
    constexpr int n = 512;
    const Vec2 r = f->radius();
    double sum = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        sum += f->evaluate(Vec2(-r.x + (x + 0.5f) * 2.f * r.x / n, -r.y + (y + 0.5f) * 2.f * r.y / n));
    const double numeric = sum * 4.0 * double(r.x) * double(r.y) / (double(n) * n);
    EXPECT_NEAR(f->integral(), numeric, 1e-4 * std::abs(numeric)) << f->to_string();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
