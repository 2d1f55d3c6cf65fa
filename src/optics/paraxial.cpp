// Paraxial y-nu matrices. The formulas for cardinal points and pupils follow from the system
// matrix M = [[A, B], [C, D]] between the first and last refracting vertices (det M = 1):
//   P = -C;  F' = z_last + A n'/P;  F = z_first - D n/P;  H = F + n/P;  H' = F' - n'/P;
//   N = F + n'/P;  N' = F' - n/P.
// Pupils: the plane conjugate to the stop through the surfaces in front of it (entrance) or
// behind it (exit), found by requiring B = 0 of the matrix between the two planes.
#include "optics/paraxial.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/phase_plate.h"

namespace eyetrace::optics {

namespace {

RayMatrix multiply(const RayMatrix& m, const RayMatrix& n) {  // m after n
  return {m.A * n.A + m.B * n.C, m.A * n.B + m.B * n.D, m.C * n.A + m.D * n.C, m.C * n.B + m.D * n.D};
}

// A phase plate adds its paraxial power, the mean of its curvature matrix (phase_plate.h):
// the scalar analysis sees a non-symmetric plate as its spherical equivalent, as it sees a
// biconic (sphero_cylinder.h has the full matrix).
RayMatrix refraction(const Prescription& p, int i) {
  const Surface& s = p.surfaces[i];
  if (s.role == SurfaceRole::Image) return {};
  double power = s.profile.is_flat() ? 0.0 : (s.index_after - p.index_before(i)) * s.profile.mean_curvature();  // 1/mm
  if (s.phase_plate) {
    const PlateHessian h = s.phase_plate->hessian_at_centre();
    power += 0.5 * (h.xx + h.yy);
  }
  if (power == 0.0) return {};
  return {1.0, 0.0, -power, 1.0};
}

RayMatrix transfer(double distance_mm, double index) { return {1.0, distance_mm / index, 0.0, 1.0}; }

int last_refracting(const Prescription& p) { return p.image_index() - 1; }

}  // namespace

RayMatrix system_matrix(const Prescription& p, int first, int last) {
  RayMatrix m;
  for (int i = first; i <= last; ++i) {
    m = multiply(refraction(p, i), m);
    if (i < last) m = multiply(transfer(p.surfaces[i].thickness_mm, p.surfaces[i].index_after), m);
  }
  return m;
}

double refraction_D(const Prescription& p) {
  const int last = last_refracting(p);
  const RayMatrix m = system_matrix(p, 0, last);
  const double n_img = p.surfaces[last].index_after;
  const double d = p.surfaces[last].thickness_mm;  // last vertex -> image vertex
  // Input ray (y = 1, n u = -V/1000) must reach y = 0 on the image:
  // (A + B nu) + d (C + D nu) / n' = 0.
  const double denom = m.B + d * m.D / n_img;
  if (denom == 0.0) throw OpticsError("refraction: the image surface is at the first principal plane's conjugate");
  const double nu = -(m.A + d * m.C / n_img) / denom;
  return -1000.0 * nu * p.object_index;
}

double image_position_for_refraction(const Prescription& p, double refraction_D) {
  const int last = last_refracting(p);
  const RayMatrix m = system_matrix(p, 0, last);
  const double n_img = p.surfaces[last].index_after;
  const double nu = -refraction_D / 1000.0 / p.object_index;
  const double y = m.A + m.B * nu;
  const double w = m.C + m.D * nu;
  if (w == 0.0) throw OpticsError(fmt::format("refraction {} D: the image is at infinity", refraction_D));
  const double d = -y * n_img / w;
  if (!(d > 0.0))
    throw OpticsError(fmt::format(
        "refraction {} D: the image would lie {:.4g} mm from the last surface (not behind it)", refraction_D, d));
  return p.vertex_z_mm()[last] + d;
}

void set_refraction(Prescription& p, double refraction_D) {
  const int last = last_refracting(p);
  const double z_image = image_position_for_refraction(p, refraction_D);
  p.surfaces[last].thickness_mm = z_image - p.vertex_z_mm()[last];
}

ParaxialData paraxial_analysis(const Prescription& p) {
  const int stop = p.stop_index();
  if (stop < 0) throw OpticsError("paraxial analysis: the prescription has no aperture stop");
  const int last = last_refracting(p);
  const std::vector<double> z = p.vertex_z_mm();
  const RayMatrix m = system_matrix(p, 0, last);
  const double power = -m.C;  // 1/mm
  if (std::abs(power) < 1e-12) throw OpticsError("paraxial analysis: the system is afocal");

  ParaxialData out;
  const double n = p.object_index;
  const double n_img = p.surfaces[last].index_after;
  out.power_D = power * 1000.0;
  out.object_index = n;
  out.image_index = n_img;
  out.back_focal_distance_mm = m.A * n_img / power;
  out.front_focal_distance_mm = -m.D * n / power;
  out.back_focal_point_mm = z[last] + out.back_focal_distance_mm;
  out.front_focal_point_mm = z[0] + out.front_focal_distance_mm;
  out.front_principal_point_mm = out.front_focal_point_mm + n / power;
  out.back_principal_point_mm = out.back_focal_point_mm - n_img / power;
  out.front_nodal_point_mm = out.front_focal_point_mm + n_img / power;
  out.back_nodal_point_mm = out.back_focal_point_mm - n / power;
  out.front_focal_length_mm = -n / power;
  out.back_focal_length_mm = n_img / power;

  const double stop_diameter = p.stop_diameter_mm();
  // Entrance pupil: matrix from the first vertex to the stop plane; the object-space plane at
  // s = n B / A is conjugate to the stop with magnification (stop / pupil) A.
  {
    RayMatrix ms = stop == 0 ? RayMatrix{} : system_matrix(p, 0, stop - 1);
    if (stop > 0) ms = multiply(transfer(p.surfaces[stop - 1].thickness_mm, p.surfaces[stop - 1].index_after), ms);
    out.entrance_pupil.position_mm = z[0] + n * ms.B / ms.A;
    out.entrance_pupil.magnification = 1.0 / ms.A;
    out.entrance_pupil.diameter_mm = stop_diameter / std::abs(ms.A);
    out.entrance_pupil.centre_x_mm = p.surfaces[stop].placement.decentre_x_mm / ms.A;
    out.entrance_pupil.centre_y_mm = p.surfaces[stop].placement.decentre_y_mm / ms.A;
  }
  // Exit pupil: matrix from the stop plane to the last vertex; the image-space plane at
  // d = -n' B / D behind the last vertex is conjugate to the stop with magnification 1 / D.
  {
    const RayMatrix m2 = system_matrix(p, stop, last);
    out.exit_pupil.position_mm = z[last] - n_img * m2.B / m2.D;
    out.exit_pupil.magnification = 1.0 / m2.D;
    out.exit_pupil.diameter_mm = stop_diameter / std::abs(m2.D);
    out.exit_pupil.centre_x_mm = p.surfaces[stop].placement.decentre_x_mm / m2.D;
    out.exit_pupil.centre_y_mm = p.surfaces[stop].placement.decentre_y_mm / m2.D;
  }
  out.refraction_D = refraction_D(p);
  out.axial_length_mm = z.back() - z[0];
  out.far_point_m = out.refraction_D == 0.0 ? std::numeric_limits<double>::infinity() : -1.0 / out.refraction_D;
  return out;
}

}  // namespace eyetrace::optics
