// Biconic sag, slopes and the iterative ray intersection (see biconic_surface.h).
#include "optics/biconic_surface.h"

#include <cmath>
#include <limits>
#include <numbers>

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

BiconicSag biconic_sag(const SurfaceProfile& s, double u, double v) {
  const double c1 = s.curvature, c2 = s.cross_curvature;
  const double a = (1.0 + s.conic) * c1 * c1, b = (1.0 + s.cross_conic) * c2 * c2;
  const double radicand = 1.0 - a * u * u - b * v * v;
  if (!(radicand > 0.0)) return {};  // at or beyond the rim, or NaN
  const double root = std::sqrt(radicand), one_plus = 1.0 + root;
  const double numerator = c1 * u * u + c2 * v * v;
  // d/du of N / (1 + S) with dS/du = -a u / S: (2 c1 u (1 + S) + N a u / S) / (1 + S)^2; for a
  // conic (c1 = c2, a = b) this reduces to c r / S, the conic's slope.
  const double inv = 1.0 / (one_plus * one_plus);
  return {true, numerator / one_plus, u * (2.0 * c1 * one_plus + numerator * a / root) * inv,
          v * (2.0 * c2 * one_plus + numerator * b / root) * inv};
}

namespace {

struct Line {  // the ray in the meridian frame
  double ou, ov, oz, du, dv, dz;
  double u(double t) const { return ou + t * du; }
  double v(double t) const { return ov + t * dv; }
};

// The start of the iteration: the first crossing of the vertex sheet of the conic of the
// meridian that reaches least far (the larger (1+Q) c^2). That conic's sheet lies inside the
// biconic's domain (the rim ellipse), so the start point has a finite sag and slope, and it
// touches the biconic along that meridian, so the start lies close to the biconic's own first
// crossing. Its root choice is the conic kernel's (trace_kernel.h): the first crossing of the
// vertex sheet at t >= -t_tolerance. When the ray misses that conic, the crossing of the vertex
// tangent plane z = 0 is the start, if it lies inside the rim.
bool start_parameter(const SurfaceProfile& s, const Line& l, double t_tolerance, double& t) {
  const bool first =
      (1.0 + s.conic) * s.curvature * s.curvature >= (1.0 + s.cross_conic) * s.cross_curvature * s.cross_curvature;
  const SurfaceProfile start = first ? SurfaceProfile::from_curvature(s.curvature, s.conic)
                                     : SurfaceProfile::from_curvature(s.cross_curvature, s.cross_conic);
  // The start conic is symmetric about its axis, so the meridian frame serves as its frame.
  const ProfileHit h = intersect(start, {l.ou, l.ov, l.oz}, {l.du, l.dv, l.dz}, t_tolerance);
  if (h.hit) {
    t = h.t;
    return true;
  }
  if (l.dz == 0.0) return false;
  t = -l.oz / l.dz;
  return std::isfinite(t) && biconic_sag(s, l.u(t), l.v(t)).valid;
}

// g(t) = z(t) - sag(u(t), v(t)) and its derivative; valid false beyond the rim.
struct Residual {
  bool valid;
  double g, slope;
};
Residual residual(const SurfaceProfile& s, const Line& l, double t) {
  const BiconicSag at = biconic_sag(s, l.u(t), l.v(t));
  if (!at.valid) return {false, 0.0, 0.0};
  return {true, l.oz + t * l.dz - at.z, l.dz - (at.dz_du * l.du + at.dz_dv * l.dv)};
}

// Newton's method on g from t (see intersect_biconic). Returns false when it stops without
// meeting the convergence test.
bool newton(const SurfaceProfile& s, const Line& l, double& t) {
  // The residual at the new t is the one the step's domain check computed: one sag per step.
  Residual r = residual(s, l, t);
  for (int it = 0; it < kBiconicMaxIterations; ++it) {
    if (!r.valid || !(r.slope != 0.0) || !std::isfinite(r.g)) return false;
    double step = -r.g / r.slope;
    if (!std::isfinite(step)) return false;
    Residual next = residual(s, l, t + step);
    int halvings = 0;
    while (!next.valid) {
      if (++halvings > 60) return false;
      step *= 0.5;
      next = residual(s, l, t + step);
    }
    t += step;
    if (std::abs(step) <= kBiconicStepTolerance_mm) return std::abs(next.g) <= kBiconicResidualTolerance_mm;
    r = next;
  }
  return false;
}

// The part [lo, hi] of the ray parameter, from -t_tolerance on, over which the ray's projection
// lies inside the rim: a (u^2) + b (v^2) < 1 with a = (1+Q1) c1^2, b = (1+Q2) c2^2 is the
// quadratic A t^2 + 2 B t + C < 0 in t. Bounded when A > 0 (a closed biconic, or a ray crossing
// a cylinder's strip); otherwise the search ends kFarSearch_mm along the ray (far beyond any
// eye or spectacle). False when the ray never lies inside.
constexpr double kFarSearch_mm = 1e4;
bool search_interval(const SurfaceProfile& s, const Line& l, double t_tolerance, double& lo, double& hi) {
  const double a = (1.0 + s.conic) * s.curvature * s.curvature;
  const double b = (1.0 + s.cross_conic) * s.cross_curvature * s.cross_curvature;
  const double A = a * l.du * l.du + b * l.dv * l.dv, B = a * l.ou * l.du + b * l.ov * l.dv;
  const double C = a * l.ou * l.ou + b * l.ov * l.ov - 1.0;
  lo = -t_tolerance, hi = kFarSearch_mm;
  if (A > 0.0) {
    const double disc = B * B - A * C;
    if (!(disc > 0.0)) return false;
    const double q = -(B + std::copysign(std::sqrt(disc), B));
    const double r0 = C / q, r1 = q / A;
    lo = std::fmax(lo, std::fmin(r0, r1));
    hi = std::fmin(hi, std::fmax(r0, r1));
  }
  return lo < hi;
}

// The fallback when Newton from the start conic fails: g sampled at kSamples points over the
// search interval (inside the rim, where g is continuous), the first sign change bracketed and
// closed by bisection to kBiconicStepTolerance_mm, then polished by Newton. No sign change:
// the ray misses (a tangent ray touching the sheet between samples is counted as a miss).
constexpr int kSamples = 64;
ProfileHit bracketed(const SurfaceProfile& s, const Line& l, double t_tolerance) {
  double lo = 0.0, hi = 0.0;
  if (!search_interval(s, l, t_tolerance, lo, hi)) return {};
  // The ends are pulled in by a part in 1e9 so every sample lies strictly inside the rim.
  const double span = hi - lo, a = lo + 1e-9 * span, b = hi - 1e-9 * span;
  double t_prev = a;
  Residual r_prev = residual(s, l, a);
  for (int k = 1; k <= kSamples; ++k) {
    const double t_next = a + (b - a) * k / kSamples;
    const Residual r_next = residual(s, l, t_next);
    if (r_prev.valid && r_next.valid && (r_prev.g == 0.0 || (r_prev.g < 0.0) != (r_next.g < 0.0))) {
      double x0 = t_prev, x1 = t_next;
      const bool negative_first = r_prev.g < 0.0;
      for (int it = 0; it < 200 && x1 - x0 > kBiconicStepTolerance_mm; ++it) {
        const double mid = 0.5 * (x0 + x1);
        const Residual m = residual(s, l, mid);
        if (!m.valid) break;
        ((m.g < 0.0) == negative_first ? x0 : x1) = mid;
      }
      double t = 0.5 * (x0 + x1);
      const double bisected = t;
      if (!newton(s, l, t) || std::abs(t - bisected) > x1 - x0 + kBiconicStepTolerance_mm) {
        t = bisected;  // Newton left the bracket: the bisection's root, if it is one
        const Residual at = residual(s, l, t);
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
//    from the start conic's first crossing (start_parameter). A step that would leave the domain
//    (beyond the rim, where the sag does not exist) is halved until it stays inside (at most 60
//    times). Converged when a step is at most kBiconicStepTolerance_mm and the sheet is within
//    kBiconicResidualTolerance_mm of the point; kBiconicMaxIterations at most. Root choice: the
//    iteration converges to the crossing next to the start conic's first crossing, which is the
//    biconic's first crossing for every surface whose meridians differ by less than their own
//    curvature (an eye's cornea, a spectacle surface); the result is checked below.
//  - When that fails (the start conic is missed, the iteration runs against the rim, or a
//    tangent stalls it) or its root is not the first (g has another sign change before it), the
//    bracketed search over the part of the ray inside the rim takes the first sign change.
// A root behind the ray origin (t < -t_tolerance) is never taken: a sequential ray does not
// travel backwards. Nothing non-finite leaves: a ray that cannot be resolved has diverged set.
ProfileHit intersect_biconic(const SurfaceProfile& s, const glm::dvec3& o, const glm::dvec3& d, double t_tolerance) {
  const MeridianFrame m(s.axis_deg);
  const Line l{m.u(o.x, o.y), m.v(o.x, o.y), o.z, m.u(d.x, d.y), m.v(d.x, d.y), d.z};
  double t = 0.0;
  if (start_parameter(s, l, t_tolerance, t) && newton(s, l, t) && t >= -t_tolerance) {
    // The first crossing when g has one sign from the ray's start to just before t: checked at
    // the start of the search interval (an earlier crossing would flip the sign there).
    double lo = 0.0, hi = 0.0;
    if (search_interval(s, l, t_tolerance, lo, hi)) {
      const Residual first = residual(s, l, lo + 1e-9 * (hi - lo));
      const Residual before = residual(s, l, t - 1e-6);
      if (!first.valid || !before.valid || (first.g < 0.0) == (before.g < 0.0) || t - 1e-6 <= lo)
        return {true, t, false};
    } else {
      return {true, t, false};
    }
  }
  return bracketed(s, l, t_tolerance);
}

glm::dvec3 biconic_gradient(const SurfaceProfile& s, const glm::dvec3& p) {
  const MeridianFrame m(s.axis_deg);
  const BiconicSag at = biconic_sag(s, m.u(p.x, p.y), m.v(p.x, p.y));
  if (!at.valid) return glm::dvec3(std::numeric_limits<double>::infinity());
  return {m.x(at.dz_du, at.dz_dv), m.y(at.dz_du, at.dz_dv), -1.0};
}

}  // namespace eyetrace::optics
