// Optical media: a refractive index at the prescription's reference wavelength plus an optional
// dispersion law that gives the index at any other wavelength.
//
// The dispersion law is used for the *change* of index from the reference wavelength:
//   index_at(lambda) = index + law(lambda) - law(reference_wavelength).
// Why: the tabulated indices (e.g. Navarro's 1.376 at 589.3 nm) are what the published paraxial
// constants are computed from, and the fitted laws miss them in the 4th decimal; anchoring keeps
// the reference-wavelength eye exactly the published one while the colour dependence still
// follows the law. The difference from the raw law is <= 1.5e-4 in index.
#pragma once

#include <array>
#include <string>

namespace eyetrace::optics {

enum class DispersionLaw {
  None,               // constant index (pbrt lens files, and anything without dispersion data)
  NavarroHerzberger,  // Navarro 1985: weights of the indices at 365, 486.1, 656.3, 1014 nm
  Cornu,              // n(lambda) = n_inf + K / (lambda - lambda0), lambda in nm (Le Grand)
  AbbeLinear,         // n(lambda) = nd + (lambda - 589.3)(nd - 1) / (Vd (486.1 - 656.3)) (Arizona)
};

struct Dispersion {
  DispersionLaw law = DispersionLaw::None;
  std::array<double, 4> herzberger_indices{};  // NavarroHerzberger: n(365), n(486.1), n(656.3), n(1014)
  double cornu_n_inf = 0.0;                    // Cornu
  double cornu_k_nm = 0.0;                     // Cornu
  double cornu_lambda0_nm = 130.0;             // Cornu
  double abbe_nd = 0.0;                        // AbbeLinear
  double abbe_vd = 0.0;                        // AbbeLinear

  // The raw law at lambda (nm). For None returns 0 (no change with wavelength).
  double evaluate(double lambda_nm) const;
};

struct Medium {
  std::string name;
  double index = 1.0;  // at reference_wavelength_nm
  double reference_wavelength_nm = 589.3;
  Dispersion dispersion;

  double index_at(double lambda_nm) const {
    if (dispersion.law == DispersionLaw::None || lambda_nm == reference_wavelength_nm) return index;
    return index + dispersion.evaluate(lambda_nm) - dispersion.evaluate(reference_wavelength_nm);
  }
};

// Navarro et al. (1985) Herzberger-type interpolation; lambda in nm. Exposed for tests.
double navarro_herzberger_index(const std::array<double, 4>& indices, double lambda_nm);

// Wavelength range over which the dispersion laws are used (the Herzberger fit's reference
// wavelengths span 365-1014 nm).
inline constexpr double kMinWavelength_nm = 360.0;
inline constexpr double kMaxWavelength_nm = 1020.0;

}  // namespace eyetrace::optics
