// Refraction from Zernike coefficients (see wavefront_refraction.h).
#include "optics/wavefront_refraction.h"

#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/zernike.h"

namespace eyetrace::optics {

namespace {

void check(const std::vector<double>& c, double r) {
  if (c.size() < 6) throw OpticsError(fmt::format("refraction: {} Zernike terms, 6 (to j = 5) needed", c.size()));
  if (!(r > 0.0 && std::isfinite(r))) throw OpticsError(fmt::format("refraction: pupil radius {} mm", r));
}

// The rho^2 coefficient of the (normalised) terms of angular frequency m, summed with their
// coefficients: the wavefront's curvature at the pupil centre in that angular component.
double rho2_coefficient(const std::vector<double>& c, int m) {
  double sum = 0.0;
  for (int j = 0; j < static_cast<int>(c.size()); ++j) {
    const ZernikeIndex z = zernike_index(j);
    if (z.m != m) continue;
    const double normalisation = std::sqrt((m == 0 ? 1.0 : 2.0) * (z.n + 1));
    sum += c[j] * normalisation * zernike_radial_coefficient(z.n, z.m, 2);
  }
  return sum;
}

}  // namespace

PowerVector least_squares_refraction(const std::vector<double>& c, double r) {
  check(c, r);
  const double r2 = r * r;
  return {-4.0 * std::sqrt(3.0) * c[zernike_single_index(2, 0)] / r2,
          -2.0 * std::sqrt(6.0) * c[zernike_single_index(2, 2)] / r2,
          -2.0 * std::sqrt(6.0) * c[zernike_single_index(2, -2)] / r2};
}

// W = a0 rho^2 + a2 rho^2 cos 2theta + b2 rho^2 sin 2theta + (higher powers) near the centre, and
// rho = h / r: matching -(M h^2 + J0 h^2 cos 2theta + J45 h^2 sin 2theta) / 2 gives M = -2 a0 / r^2.
PowerVector paraxial_refraction(const std::vector<double>& c, double r) {
  check(c, r);
  const double r2 = r * r;
  return {-2.0 * rho2_coefficient(c, 0) / r2, -2.0 * rho2_coefficient(c, 2) / r2, -2.0 * rho2_coefficient(c, -2) / r2};
}

}  // namespace eyetrace::optics
