// First-order analysis of a system with biconic (astigmatic) surfaces: generalised 4x4 ray
// transfer matrices (Keating 1981, "Transference and refraction of a generalized system",
// Am J Optom Physiol Opt 58:810; the 2x2 blocks of paraxial.h become 2x2 matrices), the
// refraction at the first vertex as a symmetric dioptric power matrix, and that matrix as
// sphere, cylinder and axis (minus-cylinder convention) and as the power vector M, J0, J45
// (Thibos, Wheeler & Horner 1997, "Power vectors: an application of Fourier analysis to the
// description and statistical analysis of refractive error", Optom Vis Sci 74:367).
//
// A ray is (y, n u) with y = (x, y) heights and n u = (n u_x, n u_y) reduced angles. A surface of
// curvature matrix K (K = R(a) diag(c1, c2) R(a)^T for a biconic whose first meridian is at a)
// refracts by n u' = n u - (n' - n) K y; a gap of thickness t in index n transfers by
// y' = y + t / n (n u). A phase plate (phase_plate.h) refracts by n u' = n u - H y, H the
// curvature matrix of its wavefront at the centre. Decentrations and tilts are ignored here: to first order they add
// prism, not power (the astigmatism a tilted lens induces is of second order in the tilt and appears in the real-ray
// trace and the wavefront only).
//
// Frames: refraction_matrix_D is in the prescription's frame (x, y of the system). The clinical
// refraction (refraction_sphero_cylinder) is stated in the frame of ANSI Z80.28, as the
// wavefront's Zernike coefficients are (wavefront.h): x_osa = -x, y_osa = y, i.e. as the examiner
// facing the eye sees it, so its axis is in TABO notation (0 at the examiner's right, counter-
// clockwise) and equals 180 - the prescription-frame angle (mod 180); J45 changes sign with it.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

struct Mat2 {
  double xx = 1.0, xy = 0.0, yx = 0.0, yy = 1.0;
};

// (y, n u) -> (A y + B n u, C y + D n u).
struct RayMatrix4 {
  Mat2 A, B{0.0, 0.0, 0.0, 0.0}, C{0.0, 0.0, 0.0, 0.0}, D;
};

// The curvature matrix of a profile (1/mm): c I for a conic, 0 for a plane.
Mat2 curvature_matrix(const SurfaceProfile& profile);

// As system_matrix of paraxial.h: from just before surface `first` to just after `last`.
RayMatrix4 system_matrix4(const Prescription& p, int first, int last);

// The object vergence at the first vertex, as a symmetric matrix (D), that is focused on the
// image surface's vertex: refraction_D of paraxial.h in every meridian. For an eye the ocular
// refraction at the corneal vertex. Throws OpticsError when no such vergence exists.
Mat2 refraction_matrix_D(const Prescription& p);

struct SpheroCylinder {
  // Minus-cylinder form: sphere = the more positive principal power, cylinder = the other
  // minus it (<= 0), axis = the meridian of the sphere, in [0, 180) deg (0 when there is no
  // cylinder).
  double sphere_D = 0.0, cylinder_D = 0.0, axis_deg = 0.0;
  // Power vector: M = sphere + cylinder / 2, J0 = -cylinder/2 cos(2 axis), J45 = -cylinder/2
  // sin(2 axis).
  double M_D = 0.0, J0_D = 0.0, J45_D = 0.0;
};

// A symmetric power matrix F = [[M + J0, J45], [J45, M - J0]] (the off-diagonal terms are
// averaged) as sphere, cylinder, axis and power vector. A cylinder below kNoCylinder_D in
// magnitude counts as none (axis 0).
inline constexpr double kNoCylinder_D = 1e-9;
SpheroCylinder sphero_cylinder(const Mat2& power_D);

// A power matrix of the prescription frame in the clinical (ANSI Z80.28) frame: x mirrored.
Mat2 clinical_from_prescription(const Mat2& m);
// The angle of a meridian in TABO notation from its angle in the prescription frame (and back:
// the map is its own inverse), in [0, 180).
double tabo_axis_deg(double prescription_axis_deg);

// refraction_matrix_D as the clinical sphero-cylinder and power vector (TABO axis).
SpheroCylinder refraction_sphero_cylinder(const Prescription& p);

}  // namespace eyetrace::optics
