// The Airy pattern of a circular pupil as a probability density over angle: what diffraction at
// an aberration-free circular pupil of diameter D does to a ray's direction at wavelength
// lambda. In the normalised radius v = pi D theta / lambda (theta the angle from the geometric
// direction, radians) the intensity is (2 J1(v) / v)^2 (Airy 1835), whose integral over the
// plane is 4 pi, and the energy within v is Rayleigh's 1 - J0(v)^2 - J1(v)^2.
//
// The pattern is truncated at a dark ring (the last of `rings`, default 32: v = 101.3, where
// 0.6 % of the energy lies beyond) and renormalised, so that the density and the sampler agree
// and no sample is unbounded. Sampling inverts the radial CDF by a table (uniform in u, linear
// between nodes); the density is a table of the intensity in v (linear between nodes). Both are
// built once (Bessel functions at construction only) and are read-only afterwards, so one
// kernel serves every thread.
#pragma once

#include <vector>

namespace eyetrace::optics {

class AiryKernel {
 public:
  explicit AiryKernel(int rings = 32);

  // The normalised radius v of a sample u in [0, 1): the inverse of the truncated radial CDF.
  double sample_radius(double u) const;
  // The density over the plane of v (per unit v^2) of the truncated, renormalised pattern at
  // radius v; 0 beyond the truncation.
  double density(double v) const;
  // The truncated pattern's energy within v (1 at and beyond the truncation).
  double cdf(double v) const;
  double max_radius() const { return v_max_; }

  // The untruncated pattern, from the Bessel functions (construction, tests).
  static double intensity(double v);      // (2 J1(v) / v)^2
  static double energy_within(double v);  // 1 - J0^2 - J1^2

 private:
  double v_max_ = 0.0;
  double energy_ = 1.0;  // of the untruncated pattern within v_max_
  double inv_u_step_ = 0.0, inv_v_step_ = 0.0;
  std::vector<double> radius_of_u_;  // v at u = i / (n - 1)
  std::vector<double> intensity_;    // (2 J1 / v)^2 at v = i * v step
};

}  // namespace eyetrace::optics
