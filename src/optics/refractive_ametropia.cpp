// Refractive ametropia by the anterior corneal radius (see refractive_ametropia.h).
#include "optics/refractive_ametropia.h"

#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"

namespace eyetrace::optics {

double set_refraction_by_cornea(Prescription& eye, const Prescription& relaxed, double target_D) {
  if (eye.surfaces.empty() || eye.surfaces[0].role != SurfaceRole::Refract ||
      !eye.surfaces[0].profile.rotationally_symmetric())
    throw OpticsError("refractiveerror", "the first surface is not a rotationally symmetric refracting cornea");
  const double dn = relaxed.surfaces[0].index_after - relaxed.object_index;
  const double c0 = relaxed.surfaces[0].profile.is_flat() ? 0.0 : relaxed.surfaces[0].profile.curvature;
  const double power0_D = 1000.0 * dn * c0;
  const double power_D = refraction_D(relaxed) + power0_D - target_D;
  const double c = power_D / dn / 1000.0;
  // A convex cornea of at least 3 mm radius: a steeper one is not an eye's (keratoconus reaches
  // about 5 mm) and would not span the cornea's clear aperture.
  if (!(c > 0.0 && c <= 1.0 / 3.0))
    throw OpticsError("refractiveerror",
                      fmt::format("{} D by corneal power needs an anterior cornea of {:.4g} D (radius {:.4g} mm), not "
                                  "a convex cornea of radius >= 3 mm; use \"axial\" ametropia",
                                  target_D, power_D, 1.0 / c));
  eye.surfaces[0].profile = SurfaceProfile::from_curvature(c, eye.surfaces[0].profile.conic);
  return 1.0 / c;
}

}  // namespace eyetrace::optics
