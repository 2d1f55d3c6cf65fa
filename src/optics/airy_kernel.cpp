#include "optics/airy_kernel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

constexpr int kInverseNodes = 16384;      // u nodes of the inverse CDF
constexpr double kIntensityStep = 0.005;  // v step of the intensity table (rings are pi apart)

// The k-th zero of J1 (k >= 1) by bisection around McMahon's estimate (k + 1/4) pi.
double j1_zero(int k) {
  double lo = (k + 0.25) * std::numbers::pi - 0.5, hi = lo + 1.0;
  const double sign_lo = std::cyl_bessel_j(1.0, lo);
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::cyl_bessel_j(1.0, mid) * sign_lo > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double AiryKernel::intensity(double v) {
  if (std::abs(v) < 1e-6) return 1.0 - v * v / 4.0;  // 2 J1(v) / v = 1 - v^2 / 8 + ...
  const double a = 2.0 * std::cyl_bessel_j(1.0, v) / v;
  return a * a;
}

double AiryKernel::energy_within(double v) {
  const double j0 = std::cyl_bessel_j(0.0, v), j1 = std::cyl_bessel_j(1.0, v);
  return 1.0 - j0 * j0 - j1 * j1;
}

AiryKernel::AiryKernel(int rings) {
  if (rings < 1 || rings > 1000) throw OpticsError("the Airy kernel needs 1 to 1000 rings");
  v_max_ = j1_zero(rings);
  energy_ = energy_within(v_max_);
  // Inverse CDF: v(u) by bisection on the renormalised energy (monotone in v).
  radius_of_u_.resize(kInverseNodes);
  inv_u_step_ = kInverseNodes - 1;
  for (int i = 0; i < kInverseNodes; ++i) {
    const double target = energy_ * i / (kInverseNodes - 1);
    double lo = 0.0, hi = v_max_;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (energy_within(mid) < target ? lo : hi) = mid;
    }
    radius_of_u_[size_t(i)] = i == kInverseNodes - 1 ? v_max_ : 0.5 * (lo + hi);
  }
  const int n = int(std::ceil(v_max_ / kIntensityStep)) + 2;
  intensity_.resize(size_t(n));
  inv_v_step_ = 1.0 / kIntensityStep;
  for (int i = 0; i < n; ++i) intensity_[size_t(i)] = intensity(i * kIntensityStep);
}

double AiryKernel::sample_radius(double u) const {
  const double x = std::clamp(u, 0.0, 1.0) * inv_u_step_;
  const int i = std::min(int(x), kInverseNodes - 2);
  const double t = x - i;
  return radius_of_u_[size_t(i)] + t * (radius_of_u_[size_t(i) + 1] - radius_of_u_[size_t(i)]);
}

// The plane integral of (2 J1 / v)^2 within v_max is 4 pi energy_ (4 pi for the whole plane).
double AiryKernel::density(double v) const {
  if (!(v >= 0.0 && v <= v_max_)) return 0.0;
  const double x = v * inv_v_step_;
  const int i = std::min(int(x), int(intensity_.size()) - 2);
  const double t = x - i;
  const double value = intensity_[size_t(i)] + t * (intensity_[size_t(i) + 1] - intensity_[size_t(i)]);
  return value / (4.0 * std::numbers::pi * energy_);
}

double AiryKernel::cdf(double v) const {
  if (!(v > 0.0)) return 0.0;
  return v >= v_max_ ? 1.0 : energy_within(v) / energy_;
}

}  // namespace eyetrace::optics
