// Navarro, Santamaria & Bescos (1985) accommodation model as a pure function: base prescription
// (the unaccommodated eye from data/eyes/navarro*.json) + accommodation parameter D -> the
// accommodated prescription. Its formulas are code; its base data is the JSON.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

// How the lens index grows with D.
enum class NavarroLensIndexLaw {
  Navarro1985,    // n_l = n_l0 + 9e-5 (10 D + D^2)  (N85 and every implementation)
  Wu2011Printed,  // n_l = n_l0 + 9e-5 ln(D + 1)      (Wu et al. 2011 Eq. 1 as printed)
};

inline constexpr double kNavarroMaxPublished_D = 10.0;  // range of the 1985 fit
inline constexpr double kNavarroMax_D = 15.0;           // accepted, as an extrapolation

// Applies, with ln = natural log (eye-models.md 5b):
//   R_a = 10.2 - 1.75 ln(D+1)        Q_a = -3.1316 - 0.34 ln(D+1)
//   R_p = -6.0 + 0.2294 ln(D+1)      Q_p = -1.0 - 0.125 ln(D+1)
//   aqueous depth T_a = 3.05 - 0.05 ln(D+1),  lens thickness T_l = 4.0 + 0.1 ln(D+1)
// and the lens index law. The axial length is held fixed (the vitreous shortens by
// 0.05 ln(D+1)): the model says nothing about the retina and a fixed axial length is the
// physical choice. The absolute values of the formulas are used (they equal the base data at
// D = 0); the base must contain surfaces named "cornea posterior", "pupil", "lens anterior",
// "lens posterior" and a medium "lens". Throws OpticsError for D outside [0, 15].
Prescription navarro_accommodate(const Prescription& base, double D, NavarroLensIndexLaw law);

// Lens index increment of the law at D (added at every wavelength).
double navarro_lens_index_shift(double D, NavarroLensIndexLaw law);

}  // namespace eyetrace::optics
