// A soft contact lens as a layer on the cornea (see contact_lens.h).
#include "optics/contact_lens.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

// The front curvature (1/mm) giving back-vertex power `power_D` in air over a back of curvature
// c_back, for centre thickness t: F1 / (1 - a F1) = X  <=>  F1 = X / (1 + a X), a = t / n.
double front_curvature(double power_D, double c_back, double t_mm) {
  const double n = kContactLensIndex;
  const double x = power_D - (1.0 - n) * c_back * 1000.0;
  const double a = t_mm / 1000.0 / n;
  return x / (1.0 + a * x) / (n - 1.0) / 1000.0;
}

SurfaceProfile front_profile(const SurfaceProfile& cornea, double power_D, double t_mm) {
  const double c = cornea.is_flat() ? 0.0 : cornea.curvature;
  if (cornea.kind != ProfileKind::Biconic)
    return SurfaceProfile::from_curvature(front_curvature(power_D, c, t_mm), cornea.conic);
  return SurfaceProfile::biconic(front_curvature(power_D, c, t_mm), cornea.conic,
                                 front_curvature(power_D, cornea.cross_curvature, t_mm), cornea.cross_conic,
                                 cornea.axis_deg);
}

// Thinnest layer (mm) at height h over azimuths every 5 degrees; -inf when the front does not
// reach h.
double edge_mm(const SurfaceProfile& front, const SurfaceProfile& cornea, double t_mm, double h) {
  if (front.max_height() < h) return -INFINITY;
  double edge = INFINITY;
  for (int k = 0; k < 72; ++k) {
    const double x = h * std::cos(k * M_PI / 36.0), y = h * std::sin(k * M_PI / 36.0);
    edge = std::min(edge, t_mm + cornea.sag(x, y) - front.sag(x, y));
  }
  return edge;
}

}  // namespace

void add_contact_lens(Prescription& eye, double power_D) {
  if (!std::isfinite(power_D) || std::abs(power_D) > kMaxContactLensPower_D)
    throw OpticsError("contactlens", fmt::format("{} D is outside [-{}, {}] D", power_D, kMaxContactLensPower_D,
                                                 kMaxContactLensPower_D));
  if (power_D == 0.0) return;
  if (eye.surfaces.empty() || eye.surfaces[0].role != SurfaceRole::Refract || eye.object_index != 1.0 ||
      !eye.surfaces[0].placement.is_identity())
    throw OpticsError("contactlens", "the first surface is not a centred cornea in air");
  const Surface& cornea = eye.surfaces[0];
  const double h = cornea.limited() ? cornea.semi_diameter_mm : 0.0;
  // Thickness: the default, or (a plus lens) the one leaving the minimum edge; the edge changes
  // one for one with t apart from the front's slight dependence on t, so a few steps converge.
  double t = kContactLensThickness_mm;
  for (int i = 0; i < 20 && h > 0.0; ++i) {
    const double edge = edge_mm(front_profile(cornea.profile, power_D, t), cornea.profile, t, h);
    if (!std::isfinite(edge))
      throw OpticsError("contactlens", fmt::format("{} D: the lens's front cannot span the cornea's {} mm clear "
                                                   "aperture",
                                                   power_D, 2 * h));
    if (edge >= kMinContactLensEdge_mm - 1e-9) break;
    t += kMinContactLensEdge_mm - edge;
  }
  Surface front{"contact lens front",   front_profile(cornea.profile, power_D, t), t, "contact lens", kContactLensIndex,
                cornea.semi_diameter_mm};
  eye.surfaces.insert(eye.surfaces.begin(), front);
  eye.media.push_back(Medium{"contact lens", kContactLensIndex, eye.reference_wavelength_nm, {}});
  eye.notes.push_back(
      fmt::format("contact lens {:+.2f} D (n {}, no dispersion): centre thickness {:.3f} mm on the "
                  "cornea; z = 0 is its front vertex",
                  power_D, kContactLensIndex, t));
  validate(eye);
}

}  // namespace eyetrace::optics
