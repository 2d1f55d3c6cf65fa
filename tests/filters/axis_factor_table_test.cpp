// The piecewise-cubic rows of a filter factor (filters/axis_factor_table.h) against the factor
// computed directly: a shifted Gaussian (std::exp here, not the filter's code) within the error
// bound the header states, a cubic reproduced to rounding, and zeros outside the support.
#include "filters/axis_factor_table.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Every tap of rows starting anywhere in [-r - 1, r + 1] against g itself.
template <class G>
double worst_row_error(const AxisFactorTable& table, const G& g, double r) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> start(-r - 1.0, r + 1.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double t0 = start(rng);
    float row[4];
    table.row(t0, 4, row);
    for (int k = 0; k < 4; ++k) {
      const double a = std::abs(t0 - k), exact = a < r ? g(a) : 0.0;
      // The float result's own rounding is not the table's error.
      worst = std::fmax(worst, std::abs(double(row[k]) - exact) - 6e-8 * std::abs(exact));
    }
  }
  return worst;
}

TEST(AxisFactorTable, ShiftedGaussianWithinItsErrorBound) {
  for (const double sigma : {0.5, 0.2, 1.5 / 256.0}) {
    const double r = 1.5, s2 = 2.0 * sigma * sigma;
    auto g = [&](double t) { return std::fmax(0.0, std::exp(-t * t / s2) - std::exp(-r * r / s2)); };
    const int segments = int(std::ceil(16.0 * r / sigma));
    const AxisFactorTable table(g, r, segments);
    // 5.1e-4 h^4 max|g''''|, max|g''''| = 12 / s2^2 (at t = 0), h = sigma / 16 or less.
    const double h = r / segments, bound = 5.1e-4 * std::pow(h, 4) * 12.0 / (s2 * s2);
    EXPECT_LT(bound, 3e-8);
    EXPECT_LE(worst_row_error(table, g, r), bound + 1e-15) << "sigma " << sigma;
  }
}

TEST(AxisFactorTable, ReproducesACubic) {
  auto g = [](double a) { return (2.0 - a) * (2.0 - a) * (1.0 + 3.0 * a); };  // zero at the radius 2
  const AxisFactorTable table(g, 2.0, 5);
  EXPECT_LE(worst_row_error(table, g, 2.0), 1e-13);
}

TEST(AxisFactorTable, ZeroOutsideTheSupportAndForNaN) {
  const AxisFactorTable table([](double a) { return 1.0 - a; }, 1.0, 8);
  float row[3];
  table.row(3.0, 3, row);  // taps at 3, 2, 1: all at or beyond the radius
  EXPECT_EQ(row[0], 0.f);
  EXPECT_EQ(row[1], 0.f);
  EXPECT_EQ(row[2], 0.f);
  table.row(std::numeric_limits<double>::quiet_NaN(), 2, row);
  EXPECT_EQ(row[0], 0.f);
  EXPECT_EQ(row[1], 0.f);
  table.row(0.25, 2, row);  // 0.25 and -0.75
  EXPECT_FLOAT_EQ(row[0], 0.75f);
  EXPECT_FLOAT_EQ(row[1], 0.25f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
