// An independent paraxial refraction for the astigmatism tests (tests/optics): the refraction
// (D) at the first vertex in one principal meridian of a system whose only non-symmetric surface
// is surface `toric` (0 by default), with curvature c0 in that meridian. y-nu matrices written here (refraction by
// (n' - n) c, transfer by t / n), V = 1000 A / B: the object vergence focused on the image vertex
// (A y + B n u = 0 with n u = -V y / 1000). Header-only: the optics tests link the optics
// library alone.
//
// meridian_refraction_at: the same for a system with any number of biconic surfaces whose
// principal meridians all lie along (or across) the meridian `angle_deg` of the prescription frame:
// each surface's curvature in that meridian is its normal curvature there (Euler:
// c1 cos^2 + c2 sin^2 of the angle from its first meridian), which is the principal one when the
// axes agree.
#pragma once

#include <cmath>

#include "optics/prescription.h"

namespace eyetrace::optics::test {

// The y-nu product over the surfaces in front of the image, each refracting surface with the
// curvature `curvature(i, surface)` gives it in the meridian; V = 1000 A / B.
template <class Curvature>
double meridian_refraction_with(const Prescription& p, Curvature curvature) {
  double A = 1, B = 0, C = 0, D = 1;
  auto apply = [&](double a, double b, double c, double d) {
    const double nA = a * A + b * C, nB = a * B + b * D, nC = c * A + d * C, nD = c * B + d * D;
    A = nA, B = nB, C = nC, D = nD;
  };
  for (int i = 0; i < p.image_index(); ++i) {
    const Surface& s = p.surfaces[i];
    const double n = i == 0 ? p.object_index : p.surfaces[i - 1].index_after;
    if (s.role == SurfaceRole::Refract) apply(1, 0, -(s.index_after - n) * curvature(i, s), 1);
    apply(1, s.thickness_mm / s.index_after, 0, 1);
  }
  return 1000.0 * A / B;
}

inline double meridian_refraction(const Prescription& p, double c0, int toric = 0) {
  return meridian_refraction_with(p, [&](int i, const Surface& s) {
    return i == toric ? c0 : (s.profile.kind == ProfileKind::Plane ? 0.0 : s.profile.curvature);
  });
}

inline double meridian_refraction_at(const Prescription& p, double angle_deg) {
  return meridian_refraction_with(p, [&](int, const Surface& s) {
    if (s.profile.kind == ProfileKind::Plane) return 0.0;
    if (s.profile.kind != ProfileKind::Biconic) return s.profile.curvature;
    const double d = (angle_deg - s.profile.axis_deg) * M_PI / 180.0;
    return s.profile.curvature * std::cos(d) * std::cos(d) + s.profile.cross_curvature * std::sin(d) * std::sin(d);
  });
}

}  // namespace eyetrace::optics::test
