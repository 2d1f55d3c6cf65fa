// Refractive ametropia: a refractive error made by the cornea's power instead of the eye's length
// (the eye cameras' `"string ametropia" "refractive"`). The anterior corneal radius is solved so
// that the eye's paraxial refraction at the corneal vertex is the requested one; its conic
// constant (asphericity), the posterior cornea, the lens and the axial length stay the model's.
// The solve is exact paraxially: the anterior cornea is the first surface and lies in the
// refraction's reference plane, so the reduced vergence just after it is the object vergence V
// plus its power P; the eye focuses on its retina the vergence V + P, whatever P is. With the
// model's power P0 and refraction R0 that vergence is R0 + P0, so the power giving refraction R
// is P = R0 + P0 - R, and the radius (n' - n) / P.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

// Sets surface 0 (a rotationally symmetric refracting cornea) of `eye` so that `relaxed` (the
// same eye, unaccommodated, whose cornea is the same) would have refraction `target_D`.
// Returns the new anterior corneal radius in mm. Throws OpticsError ("refractiveerror") when the
// power needed is not that of a convex cornea.
double set_refraction_by_cornea(Prescription& eye, const Prescription& relaxed, double target_D);

}  // namespace eyetrace::optics
