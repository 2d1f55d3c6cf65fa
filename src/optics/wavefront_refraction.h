// Refraction (the power vector M, J0, J45 in dioptres) from OSA/ANSI Zernike coefficients of a
// wavefront, two ways (Thibos, Hong, Bradley & Applegate 2004, "Accuracy and precision of
// objective refraction from wavefront aberrations", J Vision 4:329):
//
// - Least squares: the sphero-cylinder that best fits the wavefront over the whole pupil, from
//   the second-order terms alone, M = -4 sqrt(3) c(2,0) / r^2, J0 = -2 sqrt(6) c(2,2) / r^2,
//   J45 = -2 sqrt(6) c(2,-2) / r^2.
// - Paraxial curvature matching: the sphero-cylinder with the wavefront's curvature at the pupil
//   centre, i.e. from the rho^2 coefficient of every term: M = (-4 sqrt(3) c(2,0) + 12 sqrt(5)
//   c(4,0) - 24 sqrt(7) c(6,0) + ...) / r^2, J0 = (-2 sqrt(6) c(2,2) + 6 sqrt(10) c(4,2) - ...)
//   / r^2, and J45 likewise with the m = -2 terms. It agrees with paraxial optics, whatever the
//   pupil; the least-squares M moves with the spherical aberration and the pupil.
//
// Both follow from a sphero-cylinder's wavefront W = -(M (x^2 + y^2) + J0 (x^2 - y^2) + 2 J45 x y) / 2
// (W in um, x and y in mm, powers in D): W > 0 where the wavefront leads the reference, so a
// myopic eye (M < 0) has c(2,0) > 0. Coefficients in um, pupil radius r in mm.
#pragma once

#include <vector>

namespace eyetrace::optics {

struct PowerVector {
  double M_D = 0.0;    // spherical equivalent
  double J0_D = 0.0;   // Jackson cross-cylinder, axes 0 and 90 deg (x, y of the Zernike frame)
  double J45_D = 0.0;  // Jackson cross-cylinder, axes 45 and 135 deg
};

// Throws OpticsError when the coefficients stop before j = 5 (the second order) or r <= 0.
PowerVector least_squares_refraction(const std::vector<double>& zernike_um, double pupil_radius_mm);
PowerVector paraxial_refraction(const std::vector<double>& zernike_um, double pupil_radius_mm);

}  // namespace eyetrace::optics
