// Biconic sag, slopes and the iterative ray intersection (see biconic_surface.h).
#include "optics/biconic_surface.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "optics/biconic_kernel.h"

namespace eyetrace::optics {

MeridianFrame::MeridianFrame(double axis_deg) {
  // Exact for the axes an optometrist uses most (0 and 90): no 6e-17 from cos(pi/2).
  if (axis_deg == 0.0) return;
  if (axis_deg == 90.0) {
    cos_a = 0.0, sin_a = 1.0;
    return;
  }
  const double a = axis_deg * std::numbers::pi / 180.0;
  cos_a = std::cos(a), sin_a = std::sin(a);
}

BiconicTerms::BiconicTerms(const SurfaceProfile& s)
    : c1(s.curvature),
      c2(s.cross_curvature),
      a((1.0 + s.conic) * s.curvature * s.curvature),
      b((1.0 + s.cross_conic) * s.cross_curvature * s.cross_curvature),
      frame(s.axis_deg) {
  // The start conic (biconic_kernel.h, start_parameter): the meridian that reaches least far.
  const SurfaceProfile start = a >= b ? SurfaceProfile::from_curvature(s.curvature, s.conic)
                                      : SurfaceProfile::from_curvature(s.cross_curvature, s.cross_conic);
  start_c = start.is_flat() ? 0.0 : start.curvature;
  start_k = 1.0 + start.conic;
  start_kc = start_k * start_c;
  start_plane = start_c == 0.0;
}

BiconicSag biconic_sag(const SurfaceProfile& s, double u, double v) {
  const kernel::Sag<double> at = kernel::biconic_sag(BiconicTerms(s), u, v);
  if (!at.valid) return {};
  return {true, at.z, at.dz_du, at.dz_dv};
}

namespace {

using Line = kernel::Line<double>;

// The fallback when the first stage (biconic_kernel.h) does not settle a ray: g sampled at
// kSamples points over the search interval (inside the rim, where g is continuous), the first
// sign change bracketed and closed by bisection to kBiconicStepTolerance_mm, then polished by
// Newton. No sign change: the ray misses (a tangent ray touching the sheet between samples is
// counted as a miss).
constexpr int kSamples = 64;
ProfileHit bracketed(const BiconicTerms& s, const Line& l, double t_tolerance) {
  const kernel::Interval<double> in = kernel::search_interval(s, l, t_tolerance);
  if (!in.exists) return {};
  // The ends are pulled in by a part in 1e9 so every sample lies strictly inside the rim.
  const double span = in.hi - in.lo, a = in.lo + 1e-9 * span, b = in.hi - 1e-9 * span;
  double t_prev = a;
  kernel::Residual<double> r_prev = kernel::residual(s, l, a);
  for (int k = 1; k <= kSamples; ++k) {
    const double t_next = a + (b - a) * k / kSamples;
    const kernel::Residual<double> r_next = kernel::residual(s, l, t_next);
    if (r_prev.valid && r_next.valid && (r_prev.g == 0.0 || (r_prev.g < 0.0) != (r_next.g < 0.0))) {
      double x0 = t_prev, x1 = t_next;
      const bool negative_first = r_prev.g < 0.0;
      for (int it = 0; it < 200 && x1 - x0 > kBiconicStepTolerance_mm; ++it) {
        const double mid = 0.5 * (x0 + x1);
        const kernel::Residual<double> m = kernel::residual(s, l, mid);
        if (!m.valid) break;
        ((m.g < 0.0) == negative_first ? x0 : x1) = mid;
      }
      double t = 0.5 * (x0 + x1);
      const double bisected = t;
      if (!kernel::newton(s, l, t, true) || std::abs(t - bisected) > x1 - x0 + kBiconicStepTolerance_mm) {
        t = bisected;  // Newton left the bracket: the bisection's root, if it is one
        const kernel::Residual<double> at = kernel::residual(s, l, t);
        if (!at.valid || !(std::abs(at.g) <= kBiconicResidualTolerance_mm)) return {false, 0.0, true};
      }
      return {true, t, false};
    }
    t_prev = t_next, r_prev = r_next;
  }
  return {};
}

}  // namespace

// The first crossing, in two stages:
//  - Newton's method on g(t) = z(t) - sag(u(t), v(t)), g'(t) = dz - (dsag/du du + dsag/dv dv),
//    from the start conic's first crossing (biconic_kernel.h: start_parameter, newton, with the
//    convergence test of biconic_surface.h). Root choice: the iteration converges to the
//    crossing next to the start conic's first crossing, which is the biconic's first crossing
//    for every surface whose meridians differ by less than their own curvature (an eye's
//    cornea, a spectacle surface); the kernel checks that g does not change sign before it.
//  - When that fails (the start conic is missed, the iteration runs against the rim, or a
//    tangent stalls it) or its root is not the first (g has another sign change before it), the
//    bracketed search over the part of the ray inside the rim takes the first sign change.
// A root behind the ray origin (t < -t_tolerance) is never taken: a sequential ray does not
// travel backwards. Nothing non-finite leaves: a ray that cannot be resolved has diverged set.
// The batch trace runs the first stage on its lanes and this second one for the lanes it
// defers, so each lane gets the one-ray answer.
ProfileHit intersect_biconic(const SurfaceProfile& profile, const glm::dvec3& o, const glm::dvec3& d,
                             double t_tolerance) {
  const BiconicTerms s(profile);
  const kernel::BiconicHit<double> h = kernel::intersect_biconic(s, o.x, o.y, o.z, d.x, d.y, d.z, t_tolerance, true);
  if (h.hit) return {true, h.t, false};
  return intersect_biconic_bracketed(s, o.x, o.y, o.z, d.x, d.y, d.z, t_tolerance);
}

ProfileHit intersect_biconic_bracketed(const BiconicTerms& s, double ox, double oy, double oz, double dx, double dy,
                                       double dz, double t_tolerance) {
  return bracketed(s, kernel::meridian_line(s, ox, oy, oz, dx, dy, dz), t_tolerance);
}

glm::dvec3 biconic_gradient(const SurfaceProfile& s, const glm::dvec3& p) {
  const kernel::Gradient<double> g = kernel::biconic_gradient(BiconicTerms(s), p.x, p.y);
  if (!g.valid) return glm::dvec3(std::numeric_limits<double>::infinity());
  return {g.x, g.y, g.z};
}

}  // namespace eyetrace::optics
