// MTF from the PSF's line-spread functions (see mtf.h).
#include "optics/mtf.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "optics/constants.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

// |OTF(k)| / OTF(0) along one axis for k = 0 .. N/2.
std::vector<double> axis_mtf(const Psf& psf, bool along_y) {
  std::vector<double> mtf;
  for (const std::complex<double>& v : axis_otf(psf, along_y)) mtf.push_back(std::abs(v));
  return mtf;
}

double interpolate(const std::vector<double>& mtf, double k) {
  const size_t i = static_cast<size_t>(std::floor(k));
  if (i + 1 >= mtf.size()) return 0.0;
  const double t = k - static_cast<double>(i);
  return (1.0 - t) * mtf[i] + t * mtf[i + 1];
}

}  // namespace

std::vector<std::complex<double>> axis_otf(const Psf& psf, bool along_y) {
  const int n = psf.fft_size;
  std::vector<double> lsf(static_cast<size_t>(n), 0.0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) lsf[static_cast<size_t>(along_y ? y : x)] += psf.at(x, y);
  double zero = 0.0;
  for (double v : lsf) zero += v;
  // The DFT of the line-spread function about index n/2 (the zero angle), the twiddle factors
  // by recurrence within each k (renormalised: the product drifts by 1e-16 a step).
  std::vector<std::complex<double>> otf(static_cast<size_t>(n / 2 + 1));
  for (int k = 0; k <= n / 2; ++k) {
    const std::complex<double> step = std::polar(1.0, -2.0 * std::numbers::pi * k / n);
    std::complex<double> twiddle = std::polar(1.0, 2.0 * std::numbers::pi * k * (n / 2) / n), sum(0.0);
    for (int i = 0; i < n; ++i, twiddle *= step) {
      sum += lsf[static_cast<size_t>(i)] * twiddle;
      if ((i & 63) == 63) twiddle /= std::abs(twiddle);
    }
    otf[static_cast<size_t>(k)] = sum / zero;
  }
  return otf;
}

double sagittal_cutoff_cpd(const Psf& psf) {
  return 2.0 * psf.pupil_radius_mm / (psf.wavelength_nm * 1e-6) * kRadPerDeg;
}

double tangential_cutoff_cpd(const Psf& psf) { return sagittal_cutoff_cpd(psf) * psf.cos_field; }

std::vector<MtfPoint> compute_mtf(const Psf& psf, const std::vector<double>& freqs_cpd) {
  const double cutoff = tangential_cutoff_cpd(psf);
  for (double f : freqs_cpd)
    if (!(f >= 0.0 && f <= cutoff))
      throw OpticsError(
          fmt::format("mtf: {} cycles/deg is beyond the diffraction cut-off {:.1f} cycles/deg (D cos(field) / lambda, "
                      "D = {:.3f} mm, {} nm, field cos {:.4f}): the MTF is 0 there",
                      f, cutoff, 2.0 * psf.pupil_radius_mm, psf.wavelength_nm, psf.cos_field));
  const std::vector<double> tangential = axis_mtf(psf, true), sagittal = axis_mtf(psf, false);
  // FFT frequency k is 1 / (N sample) cycles per radian: k = f N sample.
  std::vector<MtfPoint> out;
  for (double f : freqs_cpd) {
    const double per_rad = f / kRadPerDeg;
    MtfPoint p;
    p.freq_cpd = f;
    p.tangential = interpolate(tangential, per_rad * psf.fft_size * psf.sample_y_rad);
    p.sagittal = interpolate(sagittal, per_rad * psf.fft_size * psf.sample_x_rad);
    p.tangential_cyc_per_mm = per_rad / psf.scale.tangential_mm_per_rad;
    p.sagittal_cyc_per_mm = per_rad / psf.scale.sagittal_mm_per_rad;
    out.push_back(p);
  }
  return out;
}

double diffraction_limited_mtf(double nu) {
  if (!(nu < 1.0)) return 0.0;
  nu = std::max(nu, 0.0);
  return 2.0 / std::numbers::pi * (std::acos(nu) - nu * std::sqrt(1.0 - nu * nu));
}

}  // namespace eyetrace::optics
