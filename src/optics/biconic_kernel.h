// The biconic's sag, slopes and first stage of its ray intersection (biconic_surface.h states the
// profile and the convergence test; biconic_surface.cpp's intersect_biconic the root choice),
// written once for a lane type V like the conic kernel (trace_kernel.h): V = double for one ray
// (biconic_surface.cpp), V = an xsimd batch for the placed surfaces of a batch trace
// (placed_kernel.h). The lanes iterate in lock step: a lane that has converged or failed is
// frozen (its values are kept by selects, never recomputed), so every lane does the arithmetic
// of the one-ray iteration in the same order and has its bits. The rare lanes this stage does not
// settle (no start point, no convergence, or a root that is not the first crossing) are returned
// as `deferred`, for the bracketed search (intersect_biconic_bracketed, one ray at a time).
//
// Internal to the optics library: included by biconic_surface.cpp and placed_kernel.h.
#pragma once

#include "optics/biconic_surface.h"
#include "optics/trace_kernel.h"

namespace eyetrace::optics::kernel {
namespace {

// The sag and its slopes at (u, v) of the meridian frame; valid false at or beyond the rim (the
// radicand is not > 0, NaN included), where the other values are meaningless but finite.
template <class V>
struct Sag {
  Mask<V> valid;
  V z, dz_du, dz_dv;
};

template <class V>
EYETRACE_KERNEL_INLINE Sag<V> biconic_sag(const BiconicTerms& s, const V& u, const V& v) {
  const V radicand = 1.0 - s.a * u * u - s.b * v * v;
  const Mask<V> valid = radicand > 0.0;
  const V root = sqrt(select(valid, radicand, V(1.0)));
  const V one_plus = 1.0 + root;
  const V numerator = s.c1 * u * u + s.c2 * v * v;
  // d/du of N / (1 + S) with dS/du = -a u / S: (2 c1 u (1 + S) + N a u / S) / (1 + S)^2; for a
  // conic (c1 = c2, a = b) this reduces to c r / S, the conic's slope.
  const V inv = 1.0 / (one_plus * one_plus);
  return {valid, numerator / one_plus, u * (2.0 * s.c1 * one_plus + numerator * s.a / root) * inv,
          v * (2.0 * s.c2 * one_plus + numerator * s.b / root) * inv};
}

// The ray in the meridian frame.
template <class V>
struct Line {
  V ou, ov, oz, du, dv, dz;
  V u(const V& t) const { return ou + t * du; }
  V v(const V& t) const { return ov + t * dv; }
};

template <class V>
Line<V> meridian_line(const BiconicTerms& s, const V& ox, const V& oy, const V& oz, const V& dx, const V& dy,
                      const V& dz) {
  const MeridianFrame& m = s.frame;
  return {m.cos_a * ox + m.sin_a * oy, -m.sin_a * ox + m.cos_a * oy, oz,
          m.cos_a * dx + m.sin_a * dy, -m.sin_a * dx + m.cos_a * dy, dz};
}

// g(t) = z(t) - sag(u(t), v(t)) and its derivative; valid false beyond the rim.
template <class V>
struct Residual {
  Mask<V> valid;
  V g, slope;
};

template <class V>
EYETRACE_KERNEL_INLINE Residual<V> residual(const BiconicTerms& s, const Line<V>& l, const V& t) {
  const Sag<V> at = biconic_sag(s, l.u(t), l.v(t));
  return {at.valid, l.oz + t * l.dz - at.z, l.dz - (at.dz_du * l.du + at.dz_dv * l.dv)};
}

// The start of the iteration: the first crossing of the vertex sheet of the conic of the
// meridian that reaches least far (the larger (1+Q) c^2). That conic's sheet lies inside the
// biconic's domain (the rim ellipse), so the start point has a finite sag and slope, and it
// touches the biconic along that meridian, so the start lies close to the biconic's own first
// crossing. Its root choice is the conic kernel's (trace_kernel.h): the first crossing of the
// vertex sheet at t >= -t_tolerance. When the ray misses that conic, the crossing of the vertex
// tangent plane z = 0 is the start, if it lies inside the rim. Returns the lanes that have one.
template <class V>
EYETRACE_KERNEL_INLINE Mask<V> start_parameter(const BiconicTerms& s, const Line<V>& l, double t_tolerance, V& t) {
  // The start conic is symmetric about its axis, so the meridian frame serves as its frame.
  const Hit<V> h =
      intersect(s.start_c, s.start_k, s.start_kc, s.start_plane, l.ou, l.ov, l.oz, l.du, l.dv, l.dz, t_tolerance);
  t = h.t;
  if (all(h.hit)) return h.hit;
  const V t_plane = -l.oz / l.dz;
  const Mask<V> on_plane = (l.dz != 0.0) & is_finite(t_plane) & biconic_sag(s, l.u(t_plane), l.v(t_plane)).valid;
  t = select(h.hit, h.t, t_plane);
  return h.hit | on_plane;
}

// Newton's method on g from t for the lanes in `active`: a step that would leave the domain
// (beyond the rim, where the sag does not exist) is halved until it stays inside (at most 60
// times); converged when a step is at most kBiconicStepTolerance_mm and the sheet is within
// kBiconicResidualTolerance_mm of the point; kBiconicMaxIterations at most. Returns the lanes
// that converged (t is their root); the others stopped without meeting the test.
template <class V>
EYETRACE_KERNEL_INLINE Mask<V> newton(const BiconicTerms& s, const Line<V>& l, V& t, Mask<V> active) {
  Mask<V> converged = active & !active;
  // The residual at the new t is the one the step's domain check computed: one sag per step.
  Residual<V> r = residual(s, l, t);
  for (int it = 0; it < kBiconicMaxIterations && any(active); ++it) {
    active = active & r.valid & (r.slope != 0.0) & is_finite(r.g);
    V step = -r.g / r.slope;
    active = active & is_finite(step);
    Residual<V> next = residual(s, l, t + step);
    // A lane's own step is unchanged by another lane's halving, so recomputing the residual
    // for every lane gives the staying lanes the bits they had.
    Mask<V> outside = active & !next.valid;
    for (int halvings = 1; any(outside); ++halvings) {
      if (halvings > 60) {
        active = active & !outside;
        break;
      }
      step = select(outside, step * 0.5, step);
      next = residual(s, l, t + step);
      outside = active & !next.valid;
    }
    t = select(active, t + step, t);
    const Mask<V> done = active & (abs(step) <= kBiconicStepTolerance_mm);
    converged = converged | (done & (abs(next.g) <= kBiconicResidualTolerance_mm));
    active = active & !done;
    r = next;
  }
  return converged;
}

// The part [lo, hi] of the ray parameter, from -t_tolerance on, over which the ray's projection
// lies inside the rim: a u^2 + b v^2 < 1 is the quadratic A t^2 + 2 B t + C < 0 in t. Bounded
// when A > 0 (a closed biconic, or a ray crossing a cylinder's strip; q != 0 there since
// disc > 0); otherwise the search ends kBiconicFarSearch_mm along the ray (far beyond any eye or
// spectacle). exists false when the ray never lies inside.
inline constexpr double kBiconicFarSearch_mm = 1e4;
template <class V>
struct Interval {
  Mask<V> exists;
  V lo, hi;
};

template <class V>
EYETRACE_KERNEL_INLINE Interval<V> search_interval(const BiconicTerms& s, const Line<V>& l, double t_tolerance) {
  const V A = s.a * l.du * l.du + s.b * l.dv * l.dv, B = s.a * l.ou * l.du + s.b * l.ov * l.dv;
  const V C = s.a * l.ou * l.ou + s.b * l.ov * l.ov - 1.0;
  const Mask<V> bounded = A > 0.0;
  const V disc = B * B - A * C;
  const V q = -(B + copysign(sqrt(select(disc > 0.0, disc, V(0.0))), B));
  const V r0 = C / q, r1 = q / A;
  const V lo = select(bounded, max_of(V(-t_tolerance), min_of(r0, r1)), V(-t_tolerance));
  const V hi = select(bounded, min_of(V(kBiconicFarSearch_mm), max_of(r0, r1)), V(kBiconicFarSearch_mm));
  return {Mask<V>((!bounded | (disc > 0.0)) & (lo < hi)), lo, hi};
}

// The biconic's first stage (intersect_biconic in biconic_surface.cpp gives the reasons): Newton
// from the start conic's first crossing; its root taken when it lies at t >= -t_tolerance (a
// sequential ray does not travel backwards) and is the first crossing: g has one sign from the
// ray's start to just before t, checked at the start of the search interval (an earlier
// crossing would flip the sign there). Lanes outside `active` are not iterated and not deferred.
template <class V>
struct BiconicHit {
  Mask<V> hit;
  V t;
  Mask<V> deferred;  // for the bracketed search
};

template <class V>
EYETRACE_KERNEL_INLINE BiconicHit<V> intersect_biconic(const BiconicTerms& s, const V& ox, const V& oy, const V& oz,
                                                       const V& dx, const V& dy, const V& dz, double t_tolerance,
                                                       const Mask<V>& active) {
  const Line<V> l = meridian_line(s, ox, oy, oz, dx, dy, dz);
  V t(0.0);
  Mask<V> found = newton(s, l, t, active & start_parameter(s, l, t_tolerance, t));
  found = found & (t >= -t_tolerance);
  if (any(found)) {
    const Interval<V> in = search_interval(s, l, t_tolerance);
    const Residual<V> first = residual(s, l, in.lo + 1e-9 * (in.hi - in.lo));
    const Residual<V> before = residual(s, l, t - 1e-6);
    found = found &
            (!in.exists | !first.valid | !before.valid | ((first.g < 0.0) == (before.g < 0.0)) | (t - 1e-6 <= in.lo));
  }
  return {found, t, Mask<V>(active & !found)};
}

// Gradient of sag(x, y) - z at a point of the sheet (local frame): (dz/dx, dz/dy, -1); valid
// false beyond the rim.
template <class V>
struct Gradient {
  Mask<V> valid;
  V x, y, z;
};

template <class V>
EYETRACE_KERNEL_INLINE Gradient<V> biconic_gradient(const BiconicTerms& s, const V& x, const V& y) {
  const MeridianFrame& m = s.frame;
  const Sag<V> at = biconic_sag(s, m.cos_a * x + m.sin_a * y, -m.sin_a * x + m.cos_a * y);
  return {at.valid, m.cos_a * at.dz_du - m.sin_a * at.dz_dv, m.sin_a * at.dz_du + m.cos_a * at.dz_dv, V(-1.0)};
}

}  // namespace
}  // namespace eyetrace::optics::kernel
