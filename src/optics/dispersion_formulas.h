// The dispersion laws' formulas, written once for one wavelength (double) and for a SIMD batch
// of wavelengths (xsimd::batch<double>): Dispersion::evaluate (medium.cpp) and the per-ray
// indices of the sequential trace (trace_kernel.h) both call these, so an index at lambda is
// the same number, bit for bit, wherever it is computed. Only + - * / appear (no fused
// multiply-add: the optics library is compiled with -ffp-contract=off), in a fixed order.
#pragma once

#include <array>

#include "optics/medium.h"

namespace eyetrace::optics::dispersion {
// Internal linkage: this header is compiled into the AVX2 kernel file too (trace_kernel.h), and
// its instantiations must not be merged with the baseline ones by the linker.
namespace {

// Navarro et al. (1985) Herzberger-type law: n(lambda) = sum_i A_i(lambda) n_i, with n_i the
// medium's indices at 365, 486.1, 656.3 and 1014 nm. The weights A_i depend on lambda alone, so
// the tracer computes them once per ray and shares them between the media.
// Coefficients a, b, c, d of A1..A4 (Navarro 1985 as quoted by Atchison & Smith 2005).
inline constexpr double kHerzberger[4][4] = {
    {0.66147196, -0.40352796, -0.28046790, 0.03385979},
    {-4.20146383, 2.73508956, 1.50543784, -0.11593235},
    {6.29834237, -4.69409935, -1.57508650, 0.10293038},
    {-1.75835059, 2.36253794, 0.35011657, -0.02085782},
};

template <class V>
std::array<V, 4> herzberger_weights(const V& lambda_nm) {
  const V lam = lambda_nm * 1e-3;  // the fit is in micrometres
  const V lam2 = lam * lam;
  const V L = 1.0 / (lam2 - 0.1673 * 0.1673);
  std::array<V, 4> w;
  for (int i = 0; i < 4; ++i) {
    const double* c = kHerzberger[i];
    w[i] = c[0] + c[1] * lam2 + c[2] * L + c[3] * L * L;
  }
  return w;
}

template <class V>
V herzberger_sum(const std::array<V, 4>& w, const std::array<double, 4>& n) {
  V sum = 0.0;
  for (int i = 0; i < 4; ++i) sum += w[i] * n[i];
  return sum;
}

// n(lambda) = n_inf + K / (lambda - lambda0), lambda in nm (Le Grand).
template <class V>
V cornu(const Dispersion& d, const V& lambda_nm) {
  return d.cornu_n_inf + d.cornu_k_nm / (lambda_nm - d.cornu_lambda0_nm);
}

// n(lambda) = nd + (lambda - 589.3)(nd - 1) / (Vd (486.1 - 656.3)) (Arizona).
template <class V>
V abbe_linear(const Dispersion& d, const V& lambda_nm) {
  return d.abbe_nd + (lambda_nm - 589.3) * (d.abbe_nd - 1.0) / (d.abbe_vd * (486.1 - 656.3));
}

// The raw law at lambda (Dispersion::evaluate), given the Herzberger weights of lambda.
template <class V>
V evaluate(const Dispersion& d, const V& lambda_nm, const std::array<V, 4>& herzberger) {
  switch (d.law) {
    case DispersionLaw::None: return V(0.0);
    case DispersionLaw::NavarroHerzberger: return herzberger_sum(herzberger, d.herzberger_indices);
    case DispersionLaw::Cornu: return cornu(d, lambda_nm);
    case DispersionLaw::AbbeLinear: return abbe_linear(d, lambda_nm);
  }
  return V(0.0);
}

}  // namespace
}  // namespace eyetrace::optics::dispersion
