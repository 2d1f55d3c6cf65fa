// Dispersion laws of the eye media (eye-models.md sections 3, 5d and 7). The formulas are in
// dispersion_formulas.h, shared with the per-ray indices of the sequential trace.
#include "optics/medium.h"

#include "optics/dispersion_formulas.h"

namespace eyetrace::optics {

double navarro_herzberger_index(const std::array<double, 4>& n, double lambda_nm) {
  return dispersion::herzberger_sum(dispersion::herzberger_weights(lambda_nm), n);
}

double Dispersion::evaluate(double lambda_nm) const {
  const std::array<double, 4> w =
      law == DispersionLaw::NavarroHerzberger ? dispersion::herzberger_weights(lambda_nm) : std::array<double, 4>{};
  return dispersion::evaluate(*this, lambda_nm, w);
}

}  // namespace eyetrace::optics
