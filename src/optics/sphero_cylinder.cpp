// Generalised (4x4) paraxial matrices and sphero-cylinders (see sphero_cylinder.h).
#include "optics/sphero_cylinder.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/biconic_surface.h"
#include "optics/optics_error.h"
#include "optics/phase_plate.h"

namespace eyetrace::optics {

namespace {

Mat2 operator*(const Mat2& a, const Mat2& b) {
  return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy, a.yx * b.xx + a.yy * b.yx, a.yx * b.xy + a.yy * b.yy};
}
Mat2 operator+(const Mat2& a, const Mat2& b) { return {a.xx + b.xx, a.xy + b.xy, a.yx + b.yx, a.yy + b.yy}; }
Mat2 operator*(double s, const Mat2& a) { return {s * a.xx, s * a.xy, s * a.yx, s * a.yy}; }

RayMatrix4 operator*(const RayMatrix4& m, const RayMatrix4& n) {  // m after n
  return {m.A * n.A + m.B * n.C, m.A * n.B + m.B * n.D, m.C * n.A + m.D * n.C, m.C * n.B + m.D * n.D};
}

// A phase plate refracts by n u' = n u - grad W = n u - H y to first order (H: its curvature
// matrix at the centre, phase_plate.h); its tilt terms add prism only and are left out, as
// decentrations are.
RayMatrix4 refraction4(const Prescription& p, int i) {
  const Surface& s = p.surfaces[i];
  if (s.role == SurfaceRole::Image) return {};
  RayMatrix4 m;
  if (!s.profile.is_flat()) m.C = -(s.index_after - p.index_before(i)) * curvature_matrix(s.profile);
  if (s.phase_plate) {
    const PlateHessian h = s.phase_plate->hessian_at_centre();
    m.C = m.C + (-1.0) * Mat2{h.xx, h.xy, h.xy, h.yy};
  }
  return m;
}

RayMatrix4 transfer4(double distance_mm, double index) {
  RayMatrix4 m;
  m.B = {distance_mm / index, 0.0, 0.0, distance_mm / index};
  return m;
}

}  // namespace

Mat2 curvature_matrix(const SurfaceProfile& s) {
  if (s.is_flat()) return {0.0, 0.0, 0.0, 0.0};
  if (s.kind != ProfileKind::Biconic) return {s.curvature, 0.0, 0.0, s.curvature};
  // R diag(c1, c2) R^T with R's first column the first meridian (cos a, sin a).
  const MeridianFrame m(s.axis_deg);
  const double c = m.cos_a, sn = m.sin_a, c1 = s.curvature, c2 = s.cross_curvature;
  const double off = (c1 - c2) * sn * c;
  return {c1 * c * c + c2 * sn * sn, off, off, c1 * sn * sn + c2 * c * c};
}

RayMatrix4 system_matrix4(const Prescription& p, int first, int last) {
  RayMatrix4 m;
  for (int i = first; i <= last; ++i) {
    m = refraction4(p, i) * m;
    if (i < last) m = transfer4(p.surfaces[i].thickness_mm, p.surfaces[i].index_after) * m;
  }
  return m;
}

Mat2 refraction_matrix_D(const Prescription& p) {
  const int last = p.image_index() - 1;
  const RayMatrix4 m = system_matrix4(p, 0, last);
  const double g = p.surfaces[last].thickness_mm / p.surfaces[last].index_after;
  // To the image vertex: A' = A + g C, B' = B + g D. An object vergence matrix V at the first
  // vertex gives the input rays n u = -V y / 1000 (y in mm, V in D), which reach the image at
  // (A' - B' V / 1000) y: zero for every y when V = 1000 n B'^-1 A' (paraxial.cpp's refraction_D
  // in every meridian).
  const Mat2 a = m.A + g * m.C, b = m.B + g * m.D;
  const double det = b.xx * b.yy - b.xy * b.yx;
  if (det == 0.0 || !std::isfinite(det))
    throw OpticsError("refraction: the image surface is at the first principal plane's conjugate in some meridian");
  const Mat2 b_inv{b.yy / det, -b.xy / det, -b.yx / det, b.xx / det};
  const Mat2 v = (1000.0 * p.object_index) * (b_inv * a);
  const double off = 0.5 * (v.xy + v.yx);  // symmetric in exact arithmetic (the system is symplectic)
  return {v.xx, off, off, v.yy};
}

SpheroCylinder sphero_cylinder(const Mat2& f) {
  SpheroCylinder out;
  out.M_D = 0.5 * (f.xx + f.yy);
  out.J0_D = 0.5 * (f.xx - f.yy);
  out.J45_D = 0.5 * (f.xy + f.yx);
  // Principal powers M +- sqrt(J0^2 + J45^2); minus cylinder: sphere = the larger.
  const double half = std::hypot(out.J0_D, out.J45_D);
  out.sphere_D = out.M_D + half;
  out.cylinder_D = -2.0 * half;
  if (std::abs(out.cylinder_D) < kNoCylinder_D) {
    out.cylinder_D = 0.0;
    return out;
  }
  // J0 = -C/2 cos 2a = half cos 2a, J45 = half sin 2a: the sphere's meridian a.
  double axis = 0.5 * std::atan2(out.J45_D, out.J0_D) * 180.0 / std::numbers::pi;
  if (axis < 0.0) axis += 180.0;
  out.axis_deg = axis >= 180.0 ? 0.0 : axis;
  return out;
}

Mat2 clinical_from_prescription(const Mat2& m) { return {m.xx, -m.xy, -m.yx, m.yy}; }

double tabo_axis_deg(double a) {
  const double mirrored = 180.0 - std::fmod(a, 180.0);
  return mirrored >= 180.0 ? mirrored - 180.0 : mirrored;
}

SpheroCylinder refraction_sphero_cylinder(const Prescription& p) {
  return sphero_cylinder(clinical_from_prescription(refraction_matrix_D(p)));
}

}  // namespace eyetrace::optics
