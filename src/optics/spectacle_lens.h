// A spectacle lens in front of an eye (the eye cameras' `spectacle*` and `vertexdistance`): a
// real two-surface lens, traced like the eye's surfaces, inserted before the cornea.
//
// Model. Front surface: a sphere of power `base_curve_D` = (n - 1) / R1 in air (a meniscus for
// positive base curves, the usual form). Back surface: a sphere, or a biconic (toric to first
// order) when there is a cylinder, whose radius in each principal meridian is solved from the
// thick-lens formula so that the lens's back-vertex power in that meridian is exactly the one
// prescribed: BVP = F1 / (1 - (t/n) F1) + F2, F2 = (1 - n) / R2. Sphere S, cylinder C, axis A are
// the lens's own prescription (either cylinder sign; axis in TABO notation as the refraction's,
// sphero_cylinder.h): BVP = S in the meridian A, S + C in the meridian A + 90. Material: index
// 1.5 by default (CR-39, n_d = 1.498), without dispersion (the lens's own chromatic aberration is
// not modelled). Diameter kSpectacleDiameter_mm (its clear aperture; rays beyond it are
// vignetted, as by a frame). The lens's back vertex lies vertex_distance_mm in front of the eye's
// first vertex (the corneal vertex, or a contact lens's front) on the axis; the prescription's
// z = 0 (and an eye camera's origin) is then the spectacle's front vertex.
#pragma once

#include <optional>

#include "optics/prescription.h"

namespace eyetrace::optics {

inline constexpr double kSpectacleDiameter_mm = 50.0;
inline constexpr double kDefaultVertexDistance_mm = 12.0;
inline constexpr double kDefaultSpectacleIndex = 1.5;
// Default centre thickness: 2 mm, or more for a lens whose edge would then be thinner than
// kMinSpectacleEdge_mm (a plus lens), so that every default lens is manufacturable.
inline constexpr double kDefaultSpectacleThickness_mm = 2.0;
inline constexpr double kMinSpectacleEdge_mm = 1.0;
inline constexpr double kMaxSpectaclePower_D = 30.0;

struct SpectacleLens {
  double sphere_D = 0.0, cylinder_D = 0.0, axis_deg = 0.0;
  double vertex_distance_mm = kDefaultVertexDistance_mm;
  double index = kDefaultSpectacleIndex;
  std::optional<double> centre_thickness_mm;  // none: the default above
  std::optional<double> base_curve_D;         // none: vogel_base_curve_D of the spherical equivalent
};

// Vogel's rule for the front (base) curve of a spectacle lens, from its spherical equivalent
// SE = S + C/2: SE + 6 D for a plus lens, SE/2 + 6 D for a minus one (Irwin Vogel's rule, as
// quoted by Brooks & Borish, "System for Ophthalmic Dispensing"; an approximation of the best-form
// (Tscherning) curves for low oblique astigmatism), but at least kMinBaseCurve_D: high minus
// lenses get a nearly flat front, as laboratories make them, rather than a concave one.
inline constexpr double kMinBaseCurve_D = 0.5;
double vogel_base_curve_D(double spherical_equivalent_D);

// Inserts the lens before surface 0 of `eye` (a validated prescription) and adds its medium and
// "air" to the media table. Throws OpticsError naming the option ("spectaclesphere",
// "spectaclecylinder", "spectacleaxis", "vertexdistance", "spectacleindex", "spectaclethickness",
// "spectaclebasecurve") for a non-finite or out-of-range value, a lens whose surfaces meet inside
// its diameter (edge thickness <= 0) or that cannot span it, and a vertex distance that puts the
// lens on or inside the eye's first surface.
void add_spectacle_lens(Prescription& eye, const SpectacleLens& lens);

}  // namespace eyetrace::optics
