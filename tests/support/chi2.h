// A reusable chi-square harness for sampling tests (after Mitsuba's chi2 test): histogram the
// samples over a grid, integrate the claimed density over each cell for the expected counts,
// pool cells whose expected counts are too small for the chi-square approximation, and turn
// Pearson's statistic into a p-value with the chi-square survival function computed here.
// Header-only; include it as "../support/chi2.h". Everything is inline, in eyetrace::chi2.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace eyetrace::chi2 {

// ---- The chi-square distribution ----

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularised upper incomplete gamma function: a power
// series for P = 1 - Q below x = a + 1, Lentz's continued fraction for Q above (as in
// Numerical Recipes, section 6.2), each where it converges fast and keeps small tails exact.
inline double regularized_gamma_q(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 1.0;
  double log_prefactor = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return std::max(0.0, 1.0 - sum * std::exp(log_prefactor));
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(log_prefactor) * h;
}

// P[X > statistic] for X chi-square distributed with `dof` degrees of freedom.
inline double survival(double statistic, double dof) {
  if (!(dof > 0.0)) return statistic > 0.0 ? 0.0 : 1.0;
  return regularized_gamma_q(0.5 * dof, 0.5 * std::max(0.0, statistic));
}

// ---- Pearson's test ----

struct Result {
  double statistic = 0.0;
  int dof = 0;
  double p_value = 1.0;
  int pooled_cells = 0;
  std::string error;  // set when the samples cannot come from the model (mass where expected = 0)

  bool passes(double significance) const { return error.empty() && dof > 0 && p_value > significance; }
  std::string summary() const {
    if (!error.empty()) return "chi-square: " + error;
    return "chi-square = " + std::to_string(statistic) + ", dof = " + std::to_string(dof) +
           ", p = " + std::to_string(p_value) + ", pooled cells = " + std::to_string(pooled_cells);
  }
};

// Accumulates Pearson terms over cells taken in order of increasing `key` (the expected count,
// or the sample count for weighted samples): cells whose key is below `min_key` go into one
// pooled cell, which keeps absorbing the next cells until its own key reaches `min_key`
// (Mitsuba's rule), so that every term has enough mass for the chi-square approximation.
class PearsonPool {
 public:
  explicit PearsonPool(double min_key) : min_key_(min_key) {}
  void add(double observed, double expected, double variance, double key) {
    if (key < min_key_ || !(variance > 0.0) || (pooled_ > 0 && pool_key_ < min_key_)) {
      pool_observed_ += observed;
      pool_expected_ += expected;
      pool_variance_ += variance;
      pool_key_ += key;
      ++pooled_;
      return;
    }
    statistic_ += (observed - expected) * (observed - expected) / variance;
    ++terms_;
  }
  // `constraints`: relations the cells satisfy by construction (1 when totals are fixed).
  Result finish(int constraints) const {
    Result r;
    r.statistic = statistic_;
    int terms = terms_;
    if (pooled_ > 0 && pool_variance_ > 0.0) {
      r.statistic += (pool_observed_ - pool_expected_) * (pool_observed_ - pool_expected_) / pool_variance_;
      ++terms;
    }
    r.dof = terms - constraints;
    r.pooled_cells = pooled_;
    r.p_value = survival(r.statistic, r.dof);
    return r;
  }

 private:
  double min_key_;
  double statistic_ = 0.0, pool_observed_ = 0.0, pool_expected_ = 0.0, pool_variance_ = 0.0, pool_key_ = 0.0;
  int terms_ = 0, pooled_ = 0;
};

inline std::vector<size_t> order_by(const std::vector<double>& key) {
  std::vector<size_t> idx(key.size());
  std::iota(idx.begin(), idx.end(), size_t(0));
  std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return key[a] < key[b]; });
  return idx;
}

// Observed counts against expected counts with the same total (one constraint, so the
// degrees of freedom are the number of terms minus one).
inline Result pearson(const std::vector<double>& observed, const std::vector<double>& expected,
                      double min_expected = 5.0) {
  Result bad;
  for (size_t i = 0; i < observed.size(); ++i)
    if (expected[i] <= 0.0 && observed[i] > 0.0) {
      bad.error = std::to_string(observed[i]) + " samples in cell " + std::to_string(i) + ", where the density is 0";
      bad.p_value = 0.0;
      return bad;
    }
  PearsonPool pool(min_expected);
  for (size_t i : order_by(expected))
    if (expected[i] > 0.0) pool.add(observed[i], expected[i], expected[i], expected[i]);
  return pool.finish(1);
}

// For weighted samples (importance sampling with weight f/pdf): per cell the sum of weights,
// the sum of squared weights and the number of samples, against the expected sum of weights.
// Each cell's variance is estimated by its sum of squared weights, so the statistic is chi-square
// only asymptotically (and, as the sums are not constrained to a total, with one dof per term);
// cells holding fewer than `min_count` samples are pooled.
inline Result weighted_pearson(const std::vector<double>& weight_sums, const std::vector<double>& weight_sq_sums,
                               const std::vector<double>& counts, const std::vector<double>& expected_sums,
                               double min_count = 20.0) {
  Result bad;
  for (size_t i = 0; i < counts.size(); ++i)
    if (expected_sums[i] == 0.0 && weight_sq_sums[i] > 0.0) {
      bad.error = "weighted samples in cell " + std::to_string(i) + ", where the expected weight is 0";
      bad.p_value = 0.0;
      return bad;
    }
  PearsonPool pool(min_count);
  for (size_t i : order_by(counts))
    if (counts[i] > 0.0 || expected_sums[i] != 0.0)
      pool.add(weight_sums[i], expected_sums[i], weight_sq_sums[i], counts[i]);
  return pool.finish(0);
}

// ---- Histograms and cell integrals ----

// An nx x ny grid over [x0, x1) x [y0, y1); samples outside are counted, not binned.
struct Grid2D {
  int nx, ny;
  double x0, x1, y0, y1;
  std::vector<double> counts, weight_sums, weight_sq_sums;
  size_t outside = 0;

  Grid2D(int nx_, int ny_, double x0_, double x1_, double y0_, double y1_)
      : nx(nx_),
        ny(ny_),
        x0(x0_),
        x1(x1_),
        y0(y0_),
        y1(y1_),
        counts(size_t(nx_) * ny_, 0.0),
        weight_sums(size_t(nx_) * ny_, 0.0),
        weight_sq_sums(size_t(nx_) * ny_, 0.0) {}

  // Index of the cell holding (x, y), or -1. The upper edges belong to the last cells.
  long cell(double x, double y) const {
    if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) return -1;
    int i = std::min(nx - 1, int((x - x0) / (x1 - x0) * nx));
    int j = std::min(ny - 1, int((y - y0) / (y1 - y0) * ny));
    return long(j) * nx + i;
  }
  void add(double x, double y, double weight = 1.0) {
    long c = cell(x, y);
    if (c < 0) {
      ++outside;
      return;
    }
    counts[size_t(c)] += 1.0;
    weight_sums[size_t(c)] += weight;
    weight_sq_sums[size_t(c)] += weight * weight;
  }
  double cell_x0(int i) const { return x0 + (x1 - x0) * i / nx; }
  double cell_y0(int j) const { return y0 + (y1 - y0) * j / ny; }
};

// The integral of f(x, y) over a rectangle: n x n panels, each by 5-point Gauss-Legendre, exact
// for polynomials of degree 9 per panel. The nodes are interior, so a density that jumps on a
// cell edge (a hemisphere's horizon) is integrated as the cell sees it.
template <typename F>
double integrate_rect(const F& f, double x0, double x1, double y0, double y1, int n = 2) {
  static const double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                   0.2369268850561891};
  double hx = (x1 - x0) / n, hy = (y1 - y0) / n, sum = 0.0;
  for (int pj = 0; pj < n; ++pj)
    for (int pi = 0; pi < n; ++pi)
      for (int j = 0; j < 5; ++j) {
        double y = y0 + hy * (pj + 0.5 + 0.5 * node[j]);
        for (int i = 0; i < 5; ++i) {
          double x = x0 + hx * (pi + 0.5 + 0.5 * node[i]);
          sum += weight[i] * weight[j] * f(x, y);
        }
      }
  return sum * hx * hy / 4.0;
}

// Expected value per cell of `scale` times the integral of `density` over the cell.
template <typename F>
std::vector<double> expected_per_cell(const Grid2D& g, const F& density, double scale, int n = 2) {
  std::vector<double> e(size_t(g.nx) * g.ny);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      e[size_t(j) * g.nx + i] =
          scale * integrate_rect(density, g.cell_x0(i), g.cell_x0(i + 1), g.cell_y0(j), g.cell_y0(j + 1), n);
  return e;
}

}  // namespace eyetrace::chi2
