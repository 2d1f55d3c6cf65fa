// OSA/ANSI Zernike polynomials and their least-squares fit, against the standard's table
// (Thibos, Applegate, Schwiegerling & Webb 2002, "Standards for reporting the optical
// aberrations of eyes", J Refract Surg 18:S652, Table 2), exact quadrature and synthetic data.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/optics_error.h"
#include "optics/zernike.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(Zernike, SingleIndexFollowsTheOsaOrder) {
  // j = 0 .. 14 as the standard's table lists them.
  const int table[15][2] = {{0, 0}, {1, -1}, {1, 1},  {2, -2}, {2, 0}, {2, 2}, {3, -3}, {3, -1},
                            {3, 1}, {3, 3},  {4, -4}, {4, -2}, {4, 0}, {4, 2}, {4, 4}};
  for (int j = 0; j < 15; ++j) {
    EXPECT_EQ(zernike_index(j).n, table[j][0]) << j;
    EXPECT_EQ(zernike_index(j).m, table[j][1]) << j;
  }
  for (int j = 0; j < 300; ++j) EXPECT_EQ(zernike_single_index(zernike_index(j).n, zernike_index(j).m), j);
  EXPECT_EQ(zernike_term_count(6), 28);
  EXPECT_THROW(zernike_single_index(3, 2), OpticsError);
  EXPECT_THROW(zernike_index(-1), OpticsError);
}

// Some of the standard's Table 2 polynomials, written out.
TEST(Zernike, MatchesTheStandardsTable) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double x = u(rng), y = u(rng), r2 = x * x + y * y, r = std::sqrt(r2), t = std::atan2(y, x);
    EXPECT_NEAR(zernike(0, x, y), 1.0, 1e-14);
    EXPECT_NEAR(zernike(1, x, y), 2.0 * r * std::sin(t), 1e-13);
    EXPECT_NEAR(zernike(3, x, y), std::sqrt(6.0) * r2 * std::sin(2 * t), 1e-13);
    EXPECT_NEAR(zernike(4, x, y), std::sqrt(3.0) * (2 * r2 - 1), 1e-13);
    EXPECT_NEAR(zernike(7, x, y), std::sqrt(8.0) * (3 * r2 * r - 2 * r) * std::sin(t), 1e-13);
    EXPECT_NEAR(zernike(12, x, y), std::sqrt(5.0) * (6 * r2 * r2 - 6 * r2 + 1), 1e-13);
    EXPECT_NEAR(zernike(13, x, y), std::sqrt(10.0) * (4 * r2 * r2 - 3 * r2) * std::cos(2 * t), 1e-13);
    EXPECT_NEAR(zernike(24, x, y), std::sqrt(7.0) * (20 * r2 * r2 * r2 - 30 * r2 * r2 + 12 * r2 - 1), 1e-12);
    EXPECT_NEAR(zernike(27, x, y), std::sqrt(14.0) * r2 * r2 * r2 * std::cos(6 * t), 1e-12);
  }
}

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n from the Chebyshev guesses).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n), w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = 0.5 * (z + 1.0);
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // 2 / ((1 - z^2) P'^2), halved for [0, 1]
  }
}

// Mean of Z_j Z_k over the unit disc = delta_jk (unit RMS, orthogonal), to order 10. The
// quadrature is exact: Gauss-Legendre in rho (24 nodes, degree 47 >= 21) and the trapezoid rule
// in theta (48 points: exact for trigonometric polynomials below degree 48 >= 20).
TEST(Zernike, OrthonormalOverTheUnitDisc) {
  const int terms = zernike_term_count(10);
  std::vector<double> rho, weight, values;
  gauss_legendre(24, rho, weight);
  std::vector<double> gram(static_cast<size_t>(terms) * terms, 0.0);
  const int n_theta = 48;
  for (size_t a = 0; a < rho.size(); ++a)
    for (int b = 0; b < n_theta; ++b) {
      const double t = 2.0 * M_PI * b / n_theta;
      zernike_all(terms, rho[a] * std::cos(t), rho[a] * std::sin(t), values);
      const double dw = weight[a] * rho[a] * (2.0 * M_PI / n_theta) / M_PI;  // area / pi
      for (int j = 0; j < terms; ++j)
        for (int k = 0; k < terms; ++k) gram[j * terms + k] += dw * values[j] * values[k];
    }
  for (int j = 0; j < terms; ++j)
    for (int k = 0; k < terms; ++k) EXPECT_NEAR(gram[j * terms + k], j == k ? 1.0 : 0.0, 1e-12) << j << " " << k;
}

// The pupil sampling trace_wavefront uses: centres of a grid x grid lattice inside the disc.
std::vector<glm::dvec2> disc_grid(int grid) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const glm::dvec2 u(-1.0 + (i + 0.5) * 2.0 / grid, -1.0 + (j + 0.5) * 2.0 / grid);
      if (u.x * u.x + u.y * u.y <= 1.0) points.push_back(u);
    }
  return points;
}

std::vector<double> synthetic(const std::vector<glm::dvec2>& points, const std::vector<double>& c) {
  std::vector<double> values, z;
  for (const glm::dvec2& p : points) {
    zernike_all(static_cast<int>(c.size()), p.x, p.y, z);
    double w = 0.0;
    for (size_t j = 0; j < c.size(); ++j) w += c[j] * z[j];
    values.push_back(w);
  }
  return values;
}

std::vector<double> known_coefficients(int terms, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<double> c(terms);
  for (double& v : c) v = u(rng);
  return c;
}

TEST(ZernikeFit, ReturnsTheCoefficientsOfASyntheticWavefront) {
  for (int grid : {16, 64, 128}) {
    const std::vector<glm::dvec2> points = disc_grid(grid);
    const std::vector<double> c = known_coefficients(zernike_term_count(6), 11 + grid);
    const ZernikeFit fit = fit_zernike(points, synthetic(points, c), 6);
    ASSERT_EQ(fit.coefficients.size(), c.size());
    for (size_t j = 0; j < c.size(); ++j) EXPECT_NEAR(fit.coefficients[j], c[j], 1e-9) << "grid " << grid << " j " << j;
    EXPECT_LT(fit.residual_rms, 1e-12);
  }
}

// Only part of the disc (as a vignetted pupil leaves): the terms are no longer orthogonal there,
// but a wavefront that is a sum of them is still fitted exactly.
TEST(ZernikeFit, ExactOnAPartOfTheDisc) {
  std::vector<glm::dvec2> points;
  for (const glm::dvec2& p : disc_grid(64))
    if (p.y < 0.7 && p.y > -0.8) points.push_back(p);
  const std::vector<double> c = known_coefficients(zernike_term_count(8), 5);
  const ZernikeFit fit = fit_zernike(points, synthetic(points, c), 8);
  for (size_t j = 0; j < c.size(); ++j) EXPECT_NEAR(fit.coefficients[j], c[j], 1e-9) << j;
}

// Terms above the fitted order are orthogonal to those below over the disc, so fitting to order 4
// a wavefront with 6th-order terms leaves its low-order coefficients alone -- up to the grid's
// departure from the disc (its staircase rim), which shrinks with the grid: the leak at 256
// samples across is under a third of that at 64 and below 1 % of the coefficients' size (2).
TEST(ZernikeFit, HigherOrdersLeakIntoLowerOnesOnlyThroughTheGridsRim) {
  const std::vector<double> c = known_coefficients(zernike_term_count(6), 3);
  auto leak = [&](int grid) {
    const std::vector<glm::dvec2> points = disc_grid(grid);
    const ZernikeFit fit = fit_zernike(points, synthetic(points, c), 4);
    double worst = 0.0;
    for (int j = 0; j < zernike_term_count(4); ++j) worst = std::max(worst, std::abs(fit.coefficients[j] - c[j]));
    return worst;
  };
  const double coarse = leak(64), fine = leak(256);
  std::printf("leak of orders 5-6 into 0-4: %.2e at 64, %.2e at 256 samples across\n", coarse, fine);
  EXPECT_LT(fine, coarse / 3.0);
  EXPECT_LT(fine, 0.02);
}

TEST(ZernikeFit, RejectsTooFewPoints) {
  const std::vector<glm::dvec2> points = disc_grid(4);  // 12 points < 28 terms
  EXPECT_THROW(fit_zernike(points, std::vector<double>(points.size(), 0.0), 6), OpticsError);
  // Points all on one line: the terms in the other direction are undetermined.
  std::vector<glm::dvec2> line;
  for (int i = 0; i < 50; ++i) line.emplace_back(-0.9 + 0.036 * i, 0.0);
  EXPECT_THROW(fit_zernike(line, std::vector<double>(line.size(), 1.0), 2), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
