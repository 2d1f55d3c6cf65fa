// OSA/ANSI Zernike polynomials and their least-squares fit (see zernike.h).
#include "optics/zernike.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

double factorial(int k) {
  double f = 1.0;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}

double normalisation(int n, int m) { return std::sqrt((m == 0 ? 1.0 : 2.0) * (n + 1)); }

}  // namespace

ZernikeIndex zernike_index(int j) {
  if (j < 0) throw OpticsError(fmt::format("zernike: index {} must be >= 0", j));
  // n is the largest order whose first index n (n + 1) / 2 is <= j.
  int n = static_cast<int>(std::floor((std::sqrt(8.0 * j + 1.0) - 1.0) / 2.0));
  while ((n + 1) * (n + 2) / 2 <= j) ++n;  // guard against the square root's rounding
  while (n * (n + 1) / 2 > j) --n;
  return {n, 2 * j - n * (n + 2)};
}

int zernike_single_index(int n, int m) {
  if (n < 0 || std::abs(m) > n || (n - std::abs(m)) % 2 != 0)
    throw OpticsError(fmt::format("zernike: (n, m) = ({}, {}) names no polynomial", n, m));
  return (n * (n + 2) + m) / 2;
}

int zernike_term_count(int max_order) { return (max_order + 1) * (max_order + 2) / 2; }

double zernike_radial_coefficient(int n, int m, int k) {
  const int am = std::abs(m);
  if (k < am || k > n || (n - k) % 2 != 0) return 0.0;
  const int s = (n - k) / 2;  // R_n^m = sum_s (-1)^s (n - s)! / (s! ((n + m)/2 - s)! ((n - m)/2 - s)!) rho^(n - 2s)
  const double c = factorial(n - s) / (factorial(s) * factorial((n + am) / 2 - s) * factorial((n - am) / 2 - s));
  return s % 2 == 0 ? c : -c;
}

void zernike_all(int count, double x, double y, std::vector<double>& values) {
  values.assign(static_cast<size_t>(count), 0.0);
  if (count <= 0) return;
  const int max_n = zernike_index(count - 1).n;
  const double rho = std::hypot(x, y);
  const double theta = std::atan2(y, x);  // atan2(0, 0) = 0: every m != 0 term is 0 there anyway
  std::vector<double> rho_pow(static_cast<size_t>(max_n) + 1, 1.0);
  for (int k = 1; k <= max_n; ++k) rho_pow[k] = rho_pow[k - 1] * rho;
  for (int j = 0; j < count; ++j) {
    const ZernikeIndex z = zernike_index(j);
    double radial = 0.0;
    for (int k = std::abs(z.m); k <= z.n; k += 2) radial += zernike_radial_coefficient(z.n, z.m, k) * rho_pow[k];
    const double angular = z.m >= 0 ? std::cos(z.m * theta) : std::sin(-z.m * theta);
    values[j] = normalisation(z.n, z.m) * radial * angular;
  }
}

double zernike(int j, double x, double y) {
  std::vector<double> v;
  zernike_all(j + 1, x, y, v);
  return v[j];
}

// Householder QR of the sample matrix rather than the normal equations: the condition number
// enters once, not squared, which keeps the fit exact to rounding also when vignetting leaves
// only part of the disc (where the terms are far from orthogonal).
ZernikeFit fit_zernike(const std::vector<glm::dvec2>& points, const std::vector<double>& values, int max_order) {
  if (max_order < 0 || max_order > 20)
    throw OpticsError(fmt::format("zernike fit: order {} not in [0, 20]", max_order));
  if (points.size() != values.size()) throw OpticsError("zernike fit: as many values as points are needed");
  const int K = zernike_term_count(max_order);
  const size_t N = points.size();
  if (N < static_cast<size_t>(K))
    throw OpticsError(fmt::format("zernike fit: {} points cannot determine {} terms (order {})", N, K, max_order));
  std::vector<double> a(N * K), b(values), row;  // a column-major: a[c * N + i]
  for (size_t i = 0; i < N; ++i) {
    zernike_all(K, points[i].x, points[i].y, row);
    for (int c = 0; c < K; ++c) a[c * N + i] = row[c];
  }
  std::vector<double> diag(K);
  for (int k = 0; k < K; ++k) {
    double* col = &a[k * N];
    double norm2 = 0.0;
    for (size_t i = k; i < N; ++i) norm2 += col[i] * col[i];
    const double norm = std::sqrt(norm2);
    // A term indistinguishable from the others on these points: the fit would be arbitrary.
    if (!(norm > 1e-10 * std::sqrt(static_cast<double>(N))))
      throw OpticsError(fmt::format("zernike fit: term j = {} is not determined by the sample points", k));
    const double alpha = col[k] > 0.0 ? -norm : norm;  // sign opposite to the pivot: no cancellation
    col[k] -= alpha;                                   // col[k..] is now the Householder vector v
    double v2 = 0.0;                                   // |v|^2 >= 2 norm2 > 0 by the choice of sign
    for (size_t i = k; i < N; ++i) v2 += col[i] * col[i];
    auto reflect = [&](double* target) {
      double dot = 0.0;
      for (size_t i = k; i < N; ++i) dot += col[i] * target[i];
      const double s = 2.0 * dot / v2;
      for (size_t i = k; i < N; ++i) target[i] -= s * col[i];
    };
    for (int c = k + 1; c < K; ++c) reflect(&a[c * N]);
    reflect(b.data());
    diag[k] = alpha;
  }
  ZernikeFit fit;
  fit.coefficients.assign(K, 0.0);
  for (int k = K - 1; k >= 0; --k) {
    double s = b[k];
    for (int c = k + 1; c < K; ++c) s -= a[c * N + k] * fit.coefficients[c];
    fit.coefficients[k] = s / diag[k];
  }
  double sum2 = 0.0;
  for (size_t i = 0; i < N; ++i) {
    zernike_all(K, points[i].x, points[i].y, row);
    double w = 0.0;
    for (int c = 0; c < K; ++c) w += fit.coefficients[c] * row[c];
    sum2 += (values[i] - w) * (values[i] - w);
  }
  fit.residual_rms = std::sqrt(sum2 / static_cast<double>(N));
  return fit;
}

}  // namespace eyetrace::optics
