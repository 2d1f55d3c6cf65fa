// Corneal cylinder and the decentred iris (see corneal_astigmatism.h).
#include "optics/corneal_astigmatism.h"

#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/sphero_cylinder.h"

namespace eyetrace::optics {

namespace {

constexpr double kMaxCornealCylinder_D = 20.0;

// Checks the options and makes surface 0 a biconic with equal meridians at axis_deg.
void make_cornea_biconic(Prescription& p, double cylinder_D, double& axis_deg) {
  if (!std::isfinite(cylinder_D) || std::abs(cylinder_D) > kMaxCornealCylinder_D)
    throw OpticsError("cylinder", fmt::format("{} D is outside [-{}, {}] D", cylinder_D, kMaxCornealCylinder_D,
                                              kMaxCornealCylinder_D));
  if (!(axis_deg >= 0.0 && axis_deg <= 180.0))
    throw OpticsError("axis", fmt::format("{} deg is outside [0, 180] deg", axis_deg));
  if (p.surfaces.empty() || p.surfaces[0].role != SurfaceRole::Refract ||
      p.surfaces[0].profile.kind == ProfileKind::Biconic)
    throw OpticsError("cylinder", "the first surface is not a rotationally symmetric refracting cornea");
  axis_deg = tabo_axis_deg(axis_deg);  // the prescription frame's angle; TABO 180 is 0
  const SurfaceProfile base = p.surfaces[0].profile;
  const double c = base.is_flat() ? 0.0 : base.curvature;
  p.surfaces[0].profile = SurfaceProfile::biconic(c, base.conic, c, base.conic, axis_deg);
}

}  // namespace

void set_corneal_cylinder(Prescription& p, double cylinder_D, double axis_deg) {
  const Prescription before = p;
  make_cornea_biconic(p, cylinder_D, axis_deg);
  if (cylinder_D == 0.0) {
    p = before;
    return;
  }
  const double dn = p.surfaces[0].index_after - p.object_index;
  p.surfaces[0].profile.cross_curvature = p.surfaces[0].profile.curvature - cylinder_D / 1000.0 / dn;
  validate(p);
}

void set_pupil_decentration(Prescription& p, double x_mm, double y_mm) {
  const int stop = p.stop_index();
  if (stop < 0) throw OpticsError("pupildecentration", "the prescription has no aperture stop");
  for (const double v : {x_mm, y_mm})
    if (!std::isfinite(v) || std::abs(v) > kMaxPupilDecentration_mm)
      throw OpticsError("pupildecentration", fmt::format("{} mm is outside [-{}, {}] mm", v, kMaxPupilDecentration_mm,
                                                         kMaxPupilDecentration_mm));
  p.surfaces[stop].placement.decentre_x_mm = x_mm;
  p.surfaces[stop].placement.decentre_y_mm = y_mm;
  validate(p);
}

}  // namespace eyetrace::optics
