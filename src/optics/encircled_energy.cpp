// Encircled energy from the PSF's Fourier series (see encircled_energy.h).
#include "optics/encircled_energy.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "optics/constants.h"
#include "optics/fft.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

glm::dvec2 centroid_um(const Psf& psf) {
  return {psf.centroid_rad.x / psf.sample_x_rad * psf.sample_x_um,
          psf.centroid_rad.y / psf.sample_y_rad * psf.sample_y_um};
}

DiscEnergy about_centroid(const Psf& psf) {
  const PsfSpectrum s = psf_spectrum(psf);
  DiscEnergy e(0.25 / std::max(s.window_x_um, s.window_y_um));
  e.add(s, centroid_um(psf), 1.0);
  return e;
}

}  // namespace

PsfSpectrum psf_spectrum(const Psf& psf) {
  if (!psf.spectrum.terms.empty()) return psf.spectrum;
  const int n = psf.fft_size;
  FftBuffer buffer(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < psf.intensity.size(); ++i) buffer.data[i] = psf.intensity[i];
  fft2_in_place(buffer.data, n);
  PsfSpectrum s;
  s.window_x_um = n * psf.sample_x_um, s.window_y_um = n * psf.sample_y_um;
  // The spectrum is zero beyond a shear of the pupil (grid samples); the window holds it whole.
  s.reach = std::min(psf.grid, n / 2 - 1);
  const double scale = 1.0 / (buffer.data[0].real() * s.window_x_um * s.window_y_um);
  const int side = 2 * s.reach + 1;
  s.terms.resize(static_cast<size_t>(side) * side);
  for (int ky = -s.reach; ky <= s.reach; ++ky)
    for (int kx = -s.reach; kx <= s.reach; ++kx)
      // The samples' zero angle is at index n/2: (-1)^(kx + ky) moves the transform's origin there.
      s.terms[static_cast<size_t>(ky + s.reach) * side + (kx + s.reach)] =
          buffer.data[static_cast<size_t>((ky + n) % n) * n + (kx + n) % n] * (((kx + ky) & 1) ? -scale : scale);
  return s;
}

void DiscEnergy::add(const PsfSpectrum& s, glm::dvec2 c, double weight) {
  zero_ += weight / (s.window_x_um * s.window_y_um);
  const int side = 2 * s.reach + 1;
  const size_t bins = static_cast<size_t>(std::hypot(s.reach / s.window_x_um, s.reach / s.window_y_um) / bin_) + 2;
  if (weight_.size() < bins) weight_.resize(bins, 0.0), rho_sum_.resize(bins, 0.0), count_.resize(bins, 0.0);
  for (int ky = -s.reach; ky <= s.reach; ++ky)
    for (int kx = -s.reach; kx <= s.reach; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const double fx = kx / s.window_x_um, fy = ky / s.window_y_um, rho = std::hypot(fx, fy);
      const std::complex<double> ik = s.terms[static_cast<size_t>(ky + s.reach) * side + (kx + s.reach)];
      const size_t b = static_cast<size_t>(rho / bin_);
      weight_[b] += weight * (ik * std::polar(1.0, kTwoPi * (fx * c.x + fy * c.y))).real();
      rho_sum_[b] += rho, count_[b] += 1.0;
    }
}

// glibc's j0 / j1 (POSIX), not std::cyl_bessel_j: the same values to about 1e-15, several times
// faster, and the radii evaluate a few hundred Bessel functions per step.
double DiscEnergy::fraction(double r) const { return fraction_and_slope(r).first; }

std::pair<double, double> DiscEnergy::fraction_and_slope(double r) const {
  // d/dr [r J1(2 pi rho r) / rho] = 2 pi r J0(2 pi rho r).
  double sum = zero_ * std::numbers::pi * r * r, slope = zero_ * kTwoPi * r;
  for (size_t b = 0; b < weight_.size(); ++b)
    if (weight_[b] != 0.0) {
      const double rho = rho_sum_[b] / count_[b], x = kTwoPi * r * rho;
      sum += weight_[b] * r * ::j1(x) / rho;
      slope += weight_[b] * kTwoPi * r * ::j0(x);
    }
  return {sum, slope};
}

double DiscEnergy::radius(double fraction, double max_radius_um) const {
  // The fraction grows with r (it is an integral of an intensity). Newton steps from inside a
  // bracket that bisection keeps: a step that leaves the bracket (or a slope the truncated series
  // makes non-positive) is replaced by the bracket's midpoint.
  double lo = 0.0, hi = max_radius_um, r = 0.5 * max_radius_um;
  for (int i = 0; i < 60 && hi - lo > 1e-7 * hi; ++i) {
    const auto [f, slope] = fraction_and_slope(r);
    (f < fraction ? lo : hi) = r;
    const double newton = r - (f - fraction) / slope;
    const double next = slope > 0.0 && newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    if (std::abs(next - r) < 1e-8 * hi) return next;
    r = next;
  }
  return 0.5 * (lo + hi);
}

std::vector<double> encircled_energy_radii(const Psf& psf, const std::vector<double>& fractions) {
  for (double f : fractions)
    if (!(f > 0.0 && f < 1.0)) throw OpticsError("encircled energy: a fraction must be in (0, 1)");
  const DiscEnergy e = about_centroid(psf);
  const double window = psf.fft_size * std::min(psf.sample_x_um, psf.sample_y_um);
  std::vector<double> radii;
  for (double f : fractions) radii.push_back(e.radius(f, 0.5 * window));
  return radii;
}

double encircled_energy_radius(const Psf& psf, double fraction) { return encircled_energy_radii(psf, {fraction})[0]; }

double encircled_energy(const Psf& psf, double radius_um) { return about_centroid(psf).fraction(radius_um); }

}  // namespace eyetrace::optics
