// Dispersion laws of the eye media (eye-models.md sections 3, 5d and 7).
#include "optics/medium.h"

namespace eyetrace::optics {

double navarro_herzberger_index(const std::array<double, 4>& n, double lambda_nm) {
  // Coefficients a, b, c, d of A1..A4 (Navarro 1985 as quoted by Atchison & Smith 2005).
  static constexpr double kCoef[4][4] = {
      {0.66147196, -0.40352796, -0.28046790, 0.03385979},
      {-4.20146383, 2.73508956, 1.50543784, -0.11593235},
      {6.29834237, -4.69409935, -1.57508650, 0.10293038},
      {-1.75835059, 2.36253794, 0.35011657, -0.02085782},
  };
  const double lam = lambda_nm * 1e-3;  // the fit is in micrometres
  const double lam2 = lam * lam;
  const double L = 1.0 / (lam2 - 0.1673 * 0.1673);
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double* c = kCoef[i];
    sum += (c[0] + c[1] * lam2 + c[2] * L + c[3] * L * L) * n[i];
  }
  return sum;
}

double Dispersion::evaluate(double lambda_nm) const {
  switch (law) {
    case DispersionLaw::None: return 0.0;
    case DispersionLaw::NavarroHerzberger: return navarro_herzberger_index(herzberger_indices, lambda_nm);
    case DispersionLaw::Cornu: return cornu_n_inf + cornu_k_nm / (lambda_nm - cornu_lambda0_nm);
    case DispersionLaw::AbbeLinear:
      return abbe_nd + (lambda_nm - 589.3) * (abbe_nd - 1.0) / (abbe_vd * (486.1 - 656.3));
  }
  return 0.0;
}

}  // namespace eyetrace::optics
