// Zernike polynomials in the OSA/ANSI standard (Thibos, Applegate, Schwiegerling & Webb 2002,
// ANSI Z80.28): single index j = (n (n + 2) + m) / 2 from 0, radial order n, angular frequency m
// (|m| <= n, n - |m| even), and the least-squares fit of sampled values to them.
//
// Z_j(rho, theta) = N_n^m R_n^|m|(rho) cos(m theta)      m >= 0
//                 = N_n^m R_n^|m|(rho) sin(|m| theta)    m < 0
// N_n^m = sqrt(2 (n + 1) / (1 + delta_m0)): each term has unit RMS over the unit disc (the mean of
// Z_j Z_k over the disc is delta_jk), so a coefficient is that term's RMS contribution and the
// RMS of a wavefront (piston removed) is the root sum of squares of its other coefficients.
// theta is counter-clockwise from +x towards +y; which physical axes x and y are is the caller's
// (wavefront.h says so for the eye).
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace eyetrace::optics {

struct ZernikeIndex {
  int n = 0;  // radial order
  int m = 0;  // angular frequency, signed (< 0: the sine term)
};

// j -> (n, m) and back; j >= 0, and (n, m) must name a polynomial (throws OpticsError otherwise).
ZernikeIndex zernike_index(int j);
int zernike_single_index(int n, int m);
// Number of terms up to and including radial order n: (n + 1)(n + 2) / 2.
int zernike_term_count(int max_order);

// Coefficient of rho^k in the unnormalised radial polynomial R_n^|m| (0 when absent).
double zernike_radial_coefficient(int n, int m, int k);

// Z_j at (x, y) in the unit disc (Cartesian, rho = |(x, y)|); also defined outside it.
double zernike(int j, double x, double y);
// Z_0 ... Z_{count - 1} at (x, y) into values (resized to count); one evaluation of the powers.
void zernike_all(int count, double x, double y, std::vector<double>& values);

struct ZernikeFit {
  std::vector<double> coefficients;  // c_j, j = 0 .. term count - 1, in the units of the values
  double residual_rms = 0.0;         // RMS of the values minus the fitted sum, over the samples
};

// Least squares: the coefficients c minimising sum_i (values_i - sum_j c_j Z_j(points_i))^2,
// points in the unit disc (normalised pupil coordinates). Throws OpticsError when the points
// cannot determine every term (fewer points than terms, or a singular system).
ZernikeFit fit_zernike(const std::vector<glm::dvec2>& points, const std::vector<double>& values, int max_order);

}  // namespace eyetrace::optics
