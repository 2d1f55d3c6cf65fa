// Encircled energy from the PSF's Fourier series (see encircled_energy.h).
#include "optics/encircled_energy.h"

#include <cmath>
#include <complex>
#include <numbers>

#include "optics/fft.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The PSF's spectrum about its centroid, summed over rings of |f|: weight[b] is the sum of
// Re(I_k exp(2 pi i f_k.c)) / (A I_0) over the frequencies of bin b, at mean |f| rho[b].
struct RadialSpectrum {
  std::vector<double> weight, rho;
  double zero = 0.0;  // the f = 0 term: 1 / A
};

RadialSpectrum radial_spectrum(const Psf& psf) {
  const int n = psf.fft_size;
  FftBuffer buffer(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < psf.intensity.size(); ++i) buffer.data[i] = psf.intensity[i];
  fft2_in_place(buffer.data, n);
  const double lx = n * psf.sample_x_um, ly = n * psf.sample_y_um;  // window, um
  const double cx = psf.centroid_rad.x / psf.sample_x_rad * psf.sample_x_um;
  const double cy = psf.centroid_rad.y / psf.sample_y_rad * psf.sample_y_um;
  const double i0 = buffer.data[0].real();
  // The spectrum is zero beyond a shear of the pupil (grid samples); the window holds it whole.
  const int reach = std::min(psf.grid, n / 2 - 1);
  const double bin = 0.25 / std::max(lx, ly);
  RadialSpectrum s;
  s.zero = 1.0 / (lx * ly);
  s.weight.assign(static_cast<size_t>(std::hypot(reach / lx, reach / ly) / bin) + 2, 0.0);
  std::vector<double> rho_sum(s.weight.size(), 0.0), count(s.weight.size(), 0.0);
  for (int ky = -reach; ky <= reach; ++ky)
    for (int kx = -reach; kx <= reach; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const double fx = kx / lx, fy = ky / ly, rho = std::hypot(fx, fy);
      // The samples' zero angle is at index n/2: (-1)^(kx + ky) moves the transform's origin there.
      const std::complex<double> ik =
          buffer.data[static_cast<size_t>((ky + n) % n) * n + (kx + n) % n] * (((kx + ky) & 1) ? -1.0 : 1.0);
      const size_t b = static_cast<size_t>(rho / bin);
      s.weight[b] += (ik * std::polar(1.0, kTwoPi * (fx * cx + fy * cy))).real() / (i0 * lx * ly);
      rho_sum[b] += rho, count[b] += 1.0;
    }
  s.rho.resize(s.weight.size());
  for (size_t b = 0; b < s.weight.size(); ++b) s.rho[b] = count[b] > 0.0 ? rho_sum[b] / count[b] : 1.0;
  return s;
}

double fraction_within(const RadialSpectrum& s, double r) {
  double sum = s.zero * std::numbers::pi * r * r;
  for (size_t b = 0; b < s.weight.size(); ++b)
    if (s.weight[b] != 0.0) sum += s.weight[b] * r * std::cyl_bessel_j(1.0, kTwoPi * r * s.rho[b]) / s.rho[b];
  return sum;
}

double radius_for(const RadialSpectrum& s, double fraction, double window_um) {
  // The fraction grows with r (it is an integral of an intensity); bisection is robust to the
  // small ripples the truncated series may have.
  double lo = 0.0, hi = 0.5 * window_um;
  for (int i = 0; i < 40 && hi - lo > 1e-7 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fraction_within(s, mid) < fraction ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

std::vector<double> encircled_energy_radii(const Psf& psf, const std::vector<double>& fractions) {
  for (double f : fractions)
    if (!(f > 0.0 && f < 1.0)) throw OpticsError("encircled energy: a fraction must be in (0, 1)");
  const RadialSpectrum s = radial_spectrum(psf);
  const double window = psf.fft_size * std::min(psf.sample_x_um, psf.sample_y_um);
  std::vector<double> radii;
  for (double f : fractions) radii.push_back(radius_for(s, f, window));
  return radii;
}

double encircled_energy_radius(const Psf& psf, double fraction) { return encircled_energy_radii(psf, {fraction})[0]; }

double encircled_energy(const Psf& psf, double radius_um) { return fraction_within(radial_spectrum(psf), radius_um); }

}  // namespace eyetrace::optics
