// Astigmatism of an eye built into its anterior cornea: the anterior corneal surface becomes a
// biconic whose meridian at axis_deg keeps the model's curvature and conic and whose cross
// meridian (axis_deg + 90) is steeper (a minus cylinder) or flatter (a plus cylinder), so the
// refraction in the axis meridian is unchanged. For the eye camera's `cylinder` and `axis`
// parameters (issue 16 part 2). The cylinder is given by the surface's own powers, (n' - n) / R
// per meridian (what a keratometer reads), and it is also the eye's refraction cylinder at the
// corneal vertex, exactly to first order: the anterior cornea lies in the refraction's reference
// plane, so its power matrix adds to the refraction matrix (sphero_cylinder.h) unchanged. At a
// spectacle plane (vertex distance d) a refraction F becomes F / (1 + d F) per meridian instead.
// Cylinders are in the refraction's (correcting lens's) sign: negative = minus cylinder, i.e. the
// cross meridian is the more powerful one. The axis is clinical, in TABO notation as
// refraction_sphero_cylinder reports it (sphero_cylinder.h), [0, 180] deg (180 = 0); the
// biconic's axis_deg in the prescription frame is tabo_axis_deg of it.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

// Surface power: (n' - n)(c_cross - c_axis) = -cylinder_D. Surface 0 must be a rotationally
// symmetric refracting surface. Throws OpticsError naming the option ("cylinder", "axis") for a
// non-finite or out-of-range value (|cylinder| > 20 D, axis outside [0, 180]).
void set_corneal_cylinder(Prescription& p, double cylinder_D, double axis_deg);

// The iris (aperture stop) moved to (x_mm, y_mm) off the axis. Throws OpticsError ("pupildecentration")
// for a non-finite value or one beyond kMaxPupilDecentration_mm.
inline constexpr double kMaxPupilDecentration_mm = 3.0;
void set_pupil_decentration(Prescription& p, double x_mm, double y_mm);

}  // namespace eyetrace::optics
