// The biconic profile: a curvature and a conic constant in each of two orthogonal principal
// meridians, the first at axis_deg from the local +x axis (towards +y). In the meridian frame
// (u along the first meridian, v along the second) its vertex sheet is
//   z = (c1 u^2 + c2 v^2) / (1 + sqrt(1 - (1+Q1) c1^2 u^2 - (1+Q2) c2^2 v^2)),
// which is the conic of conic_surface.h when c1 = c2 and Q1 = Q2, a toric-like cornea or
// spectacle surface otherwise (paraxially a sphero-cylinder: the curvatures c1, c2 in the
// principal meridians), and a cylinder when one curvature is 0. Its sag has no closed-form ray
// intersection, so intersect_biconic iterates (Newton's method), with the stated convergence
// test, step control and cap below; a ray that does not converge is reported, never NaN.
#pragma once

#include <glm/vec3.hpp>

#include "optics/conic_surface.h"

namespace eyetrace::optics {

// Newton iterations at most; a converging ray needs 3-6 (quadratic convergence from the start
// conic, which differs from the biconic by the small difference of the meridians).
inline constexpr int kBiconicMaxIterations = 50;
// Converged when a Newton step moves the ray parameter by no more than this (mm, for a unit
// direction): from there quadratic convergence leaves an error far below a nanometre...
inline constexpr double kBiconicStepTolerance_mm = 1e-12;
// ...and the point found must lie on the sheet to within this (mm); else it is not a root.
inline constexpr double kBiconicResidualTolerance_mm = 1e-9;

// The sag and its slopes at a point (u, v) of the meridian frame; valid is false where the point
// lies beyond the vertex sheet's rim (the radicand is not > 0, where the slopes are infinite).
struct BiconicSag {
  bool valid = false;
  double z = 0.0, dz_du = 0.0, dz_dv = 0.0;
};
BiconicSag biconic_sag(const SurfaceProfile& profile, double u, double v);

// (x, y) of the local frame -> (u, v) of the meridian frame (a rotation by -axis_deg), and back.
struct MeridianFrame {
  double cos_a = 1.0, sin_a = 0.0;
  explicit MeridianFrame(double axis_deg);
  double u(double x, double y) const { return cos_a * x + sin_a * y; }
  double v(double x, double y) const { return -sin_a * x + cos_a * y; }
  double x(double u, double v) const { return cos_a * u - sin_a * v; }
  double y(double u, double v) const { return sin_a * u + cos_a * v; }
};

// The numbers of a biconic its intersection works with, computed once per surface (a placed
// surface keeps them: placed_surface.h).
struct BiconicTerms {
  double c1 = 0.0, c2 = 0.0;  // the meridians' curvatures
  double a = 0.0, b = 0.0;    // (1+Q1) c1^2 and (1+Q2) c2^2: the rim is a u^2 + b v^2 = 1
  MeridianFrame frame{0.0};
  // The conic the iteration starts from (intersect_biconic says which), as the conic kernel
  // (trace_kernel.h) takes it: curvature, 1 + Q, their product, flat.
  double start_c = 0.0, start_k = 1.0, start_kc = 0.0;
  bool start_plane = true;

  BiconicTerms() = default;
  explicit BiconicTerms(const SurfaceProfile& profile);
};

// The first crossing of the ray o + t d (local frame, any |d| > 0) with the biconic's vertex
// sheet at t >= -t_tolerance. Not converged (or no root): hit false, and diverged true when the
// iteration gave up rather than finding that the ray misses.
ProfileHit intersect_biconic(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                             double t_tolerance);
// Its second stage alone (the bracketed search, see biconic_surface.cpp), for a ray o + t d the
// lane iteration (biconic_kernel.h) did not settle. Plain doubles: the AVX2 batch calls it.
ProfileHit intersect_biconic_bracketed(const BiconicTerms& terms, double ox, double oy, double oz, double dx, double dy,
                                       double dz, double t_tolerance);

// Gradient of sag(x, y) - z at a point of the sheet (local frame): (dz/dx, dz/dy, -1), i.e.
// oriented towards -z at the vertex like the conic's. Non-finite beyond the rim.
glm::dvec3 biconic_gradient(const SurfaceProfile& profile, const glm::dvec3& point);

}  // namespace eyetrace::optics
