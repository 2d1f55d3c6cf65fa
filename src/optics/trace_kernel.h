// The one ray-surface kernel of the sequential trace: conic intersection with its root choice,
// the clear-aperture and stop checks, vector Snell refraction with total internal reflection,
// and the per-ray indices at a wavelength. Every function is written once for a lane type V:
//  - V = double: one ray (CompiledSystem::trace_range, intersect() of conic_surface.h); masks
//    are bool;
//  - V = xsimd::batch<double, Arch>: W rays side by side (CompiledSystem::trace_range_batch);
//    masks are xsimd::batch_bool.
// Packed IEEE arithmetic rounds each lane exactly as the scalar instruction does, and the
// kernel uses only + - * / and sqrt in one fixed order (the optics library is compiled with
// -ffp-contract=off, so no fused multiply-add changes a rounding), so the batched trace gives
// the single-ray trace's bits. Instead of branching, the kernel computes every case and selects
// per lane; the rare ones (a ray parallel to a paraboloid's axis, a tangent at the origin, a
// zero gradient) are handled in it, not by a second code path.
//
// The biconic and placed surfaces of a system that is not rotationally symmetric have their own
// lane kernels on top of this one (biconic_kernel.h, placed_kernel.h), which refract with its
// refract(); batch_kernel.h runs a block of rays through a range of surfaces.
//
// Internal to the optics library: included by conic_surface.cpp and the headers above.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <xsimd/xsimd.hpp>

#include "optics/conic_surface.h"
#include "optics/dispersion_formulas.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics::kernel {

using trace_detail::Interface;
using trace_detail::MediumLaw;

// The kernel's functions are inlined into the surface loops (a call per surface, with its
// result returned through memory, costs the single-ray trace ~20%).
#if defined(__GNUC__) || defined(__clang__)
#define EYETRACE_KERNEL_INLINE inline __attribute__((always_inline))
#else
#define EYETRACE_KERNEL_INLINE inline
#endif

// Internal linkage: this header is compiled into the AVX2 file too, and no function of it may
// be merged by the linker with its baseline twin (an AVX2 copy would then run on any CPU).
namespace {

// ---- Lane operations -------------------------------------------------------------------------

template <class V>
using Mask = decltype(V() == V());

inline double select(bool m, double a, double b) { return m ? a : b; }
template <class A>
xsimd::batch<double, A> select(const xsimd::batch_bool<double, A>& m, const xsimd::batch<double, A>& a,
                               const xsimd::batch<double, A>& b) {
  return xsimd::select(m, a, b);
}
inline bool any(bool m) { return m; }
template <class A>
bool any(const xsimd::batch_bool<double, A>& m) {
  return xsimd::any(m);
}
inline bool all(bool m) { return m; }
template <class A>
bool all(const xsimd::batch_bool<double, A>& m) {
  return xsimd::all(m);
}
inline double sqrt(double x) { return std::sqrt(x); }
template <class A>
xsimd::batch<double, A> sqrt(const xsimd::batch<double, A>& x) {
  return xsimd::sqrt(x);
}
// |x| with the sign of y.
inline double copysign(double x, double y) { return std::copysign(x, y); }
template <class A>
xsimd::batch<double, A> copysign(const xsimd::batch<double, A>& x, const xsimd::batch<double, A>& y) {
  return xsimd::copysign(x, y);
}
inline double abs(double x) { return std::abs(x); }
template <class A>
xsimd::batch<double, A> abs(const xsimd::batch<double, A>& x) {
  return xsimd::abs(x);
}
// The smaller and larger of a and b by one compare, the same in every lane type (std::fmin's
// and the packed min's rules differ for NaN and signed zeros; callers pass neither).
template <class V>
V min_of(const V& a, const V& b) {
  return select(b < a, b, a);
}
template <class V>
V max_of(const V& a, const V& b) {
  return select(a < b, b, a);
}
inline bool is_finite(double x) { return std::isfinite(x); }
template <class A>
xsimd::batch_bool<double, A> is_finite(const xsimd::batch<double, A>& x) {
  return xsimd::isfinite(x);
}

// Lanes in memory: V::size doubles (1 for V = double), for the work done one lane at a time.
template <class V>
struct Lanes {
  static constexpr std::size_t size = V::size;
  static V load(const double* p) { return V::load_unaligned(p); }
  static void store(const V& x, double* p) { x.store_unaligned(p); }
};
template <>
struct Lanes<double> {
  static constexpr std::size_t size = 1;
  static double load(const double* p) { return *p; }
  static void store(double x, double* p) { *p = x; }
};

// Lane statuses are kept as doubles so every array of a block has one element type.
constexpr double code(TraceStatus s) { return static_cast<double>(s); }
constexpr double kOk = code(TraceStatus::Ok);

// ---- Intersection ----------------------------------------------------------------------------

template <class V>
struct Hit {
  Mask<V> hit;
  V t;  // where hit: the ray parameter of the hit point
};

// The ray o + t d (vertex frame, d need not be normalised) against the conic of curvature c and
// k = 1 + Q (kc = k c; plane = c == 0). Why each step is done this way:
//  - The implicit form F = c (x^2 + y^2 + k z^2) - 2 z has no 1/c, so planes (c = 0) and nearly
//    flat surfaces go through the same formula without loss of precision.
//  - The quadratic a t^2 + 2 b t + f = 0 is solved in the cancellation-free form
//    q = -(b + sign(b) sqrt(b^2 - a f)), t = f/q and t = q/a. The root f/q stays finite when
//    a -> 0 (a paraboloid hit by a ray nearly parallel to its axis), where the textbook formula
//    would divide a vanishing difference by a vanishing a; q/a then overflows to +-inf and is
//    rejected by the finiteness test.
//  - a == 0 exactly is linear: a plane, or a ray parallel to a paraboloid's axis (or a
//    hyperboloid's asymptote). One crossing, t = -f / 2b; none when b == 0 (a ray parallel to
//    a plane).
//  - disc < 0: the line misses the conicoid (a grazing ray that round-off pushed below 0
//    included). disc == 0 grazes: kept as a hit at the double root. q == 0 (b == 0 and f == 0)
//    is a tangent at the ray origin: both roots are t = 0.
//  - A conicoid has two sheets (hyperboloid) or two halves (sphere, ellipsoid). Solving
//    k c z^2 - 2 z + c r^2 = 0 for z gives z = (1 -+ sqrt(1 - k c^2 r^2)) / (k c); the sag
//    formula, i.e. the part containing the vertex, is the '-' branch, on which
//    1 - k c z = +sqrt(...) >= 0. The far sheet of a hyperboloid and the far half of a sphere or
//    ellipsoid have 1 - k c z <= 0. So a root lies on the physical surface iff 1 - k c z >= 0
//    (-kSheetTolerance, for round-off at the rim of a closed conic).
//  - Of the roots on that branch the first one along the ray (smallest t >= -t_tolerance) is
//    taken: a sequential ray meets each surface once, at its first physical crossing; a root
//    behind the origin would mean travelling backwards. t_tolerance lets a ray that starts on
//    the surface (the stop on the lens vertex) meet it at t = 0.
// Every lane computes every case; selects pick the one that applies. Nothing here traps or
// leaks: a lane that misses has hit false, whatever NaN or inf its unused t holds.
template <class V>
EYETRACE_KERNEL_INLINE Hit<V> intersect(double c, double k, double kc, bool plane, const V& ox, const V& oy,
                                        const V& oz, const V& dx, const V& dy, const V& dz, double t_tolerance) {
  const V b = c * (ox * dx + oy * dy + k * oz * dz) - dz;
  const V f = c * (ox * ox + oy * oy + k * oz * oz) - 2.0 * oz;
  V t0, t1;
  Mask<V> crosses;
  if (plane) {  // c == 0: a == 0 in every lane, the linear case alone
    t0 = t1 = -f / (2.0 * b);
    crosses = b != 0.0;
  } else {
    const V a = c * (dx * dx + dy * dy + k * dz * dz);
    const V disc = b * b - a * f;
    crosses = disc >= 0.0;  // false for NaN too
    const V q = -(b + copysign(sqrt(select(crosses, disc, V(0.0))), b));
    const V tq = f / q, ta = q / a;
    const Mask<V> swap = ta < tq;
    const Mask<V> tangent = q == 0.0;
    t0 = select(tangent, V(0.0), select(swap, ta, tq));
    t1 = select(tangent, V(0.0), select(swap, tq, ta));
    const Mask<V> linear = a == 0.0;
    if (any(linear)) {
      const V tl = -f / (2.0 * b);
      t0 = select(linear, tl, t0);
      t1 = select(linear, tl, t1);
      crosses = (linear & (b != 0.0)) | (!linear & crosses);
    }
  }
  const Mask<V> ok0 = is_finite(t0) & (t0 >= -t_tolerance) & (1.0 - kc * (oz + t0 * dz) >= -kSheetTolerance);
  const Mask<V> ok1 = is_finite(t1) & (t1 >= -t_tolerance) & (1.0 - kc * (oz + t1 * dz) >= -kSheetTolerance);
  return {Mask<V>(crosses & (ok0 | ok1)), select(ok0, t0, t1)};
}

// ---- One surface -------------------------------------------------------------------------------

// Refraction at a surface for the lanes: eta = n_from / n_to per lane, its square and
// 1 - eta^2; lanes with eta == 1 do not refract (equal indices). all: every lane refracts (one
// eta for all of them), so no per-lane select is needed.
template <class V>
struct Eta {
  V eta, eta2, one_minus_eta2;
  Mask<V> refracts;
  bool all;
};

template <class V>
Eta<V> eta_of(const V& eta) {
  const V eta2 = eta * eta;
  return {eta, eta2, 1.0 - eta2, eta != 1.0, false};
}

template <class V>
Eta<V> uniform_eta(double eta) {
  return {V(eta), V(eta * eta), V(1.0 - eta * eta), Mask<V>(true), true};
}

template <class V>
struct Moved {
  V status;      // kOk, or the TraceStatus that stopped the lane here
  V px, py, pz;  // where kOk: the hit point (system frame)
  V dx, dy, dz;  // where kOk: the direction after the surface
};

template <class V>
struct Refracted {
  V status;      // kOk, or why the lane stopped (a lane not kOk on entry keeps its status)
  V dx, dy, dz;  // where kOk: the direction after the surface
};

// Vector Snell with the unnormalised surface gradient g at the hit (so the normal is never
// normalised): d' = eta d + gamma g, with gamma the root of |d'| = 1 that continues forward,
//   gamma = (-eta (g.d) - sqrt(eta^2 (g.d)^2 + |g|^2 (1 - eta^2))) / |g|^2,   g turned so g.d <= 0.
// It equals the textbook eta d + (eta cos_i - cos_t) n but has one square root and one
// independent division instead of three dependent ones: the latency chain is what limits the
// camera's ray rate. A negative radicand is total internal reflection (so is a NaN one, which a
// finite ray cannot produce). A zero |g| (a conic's centre, which no true hit reaches: a hit
// computed there from a ray origin ~1e13 mm away by round-off) or a non-finite one (a biconic
// at its rim, where the slope is infinite) is reported as Missed. d and g in one frame, |d| = 1;
// lanes whose status is not kOk on entry keep it. The conic kernel (step) and the placed
// surfaces (placed_kernel.h) refract with this one function.
template <class V>
EYETRACE_KERNEL_INLINE Refracted<V> refract(V gx, V gy, V gz, const V& dx, const V& dy, const V& dz, const V& status,
                                            const Eta<V>& eta) {
  V gd = gx * dx + gy * dy + gz * dz;
  const Mask<V> flip = gd > 0.0;
  gx = select(flip, -gx, gx), gy = select(flip, -gy, gy), gz = select(flip, -gz, gz), gd = select(flip, -gd, gd);
  const V g2 = gx * gx + gy * gy + gz * gz;
  const V radicand = eta.eta2 * gd * gd + g2 * eta.one_minus_eta2;
  const Mask<V> refracted = radicand >= 0.0;
  const V gamma = (-eta.eta * gd - sqrt(select(refracted, radicand, V(0.0)))) * (1.0 / g2);
  const V refraction =
      select((g2 > 0.0) & is_finite(g2), select(refracted, V(kOk), V(code(TraceStatus::TotalInternalReflection))),
             V(code(TraceStatus::Missed)));
  const V nx = eta.eta * dx + gamma * gx, ny = eta.eta * dy + gamma * gy, nz = eta.eta * dz + gamma * gz;
  // Per-lane indices refract every lane too, unless two media have the same index at a lane's
  // wavelength: checked once, the selects below are for that case only.
  if (eta.all || all(eta.refracts)) return {select(status == kOk, refraction, status), nx, ny, nz};
  return {select((status == kOk) & eta.refracts, refraction, status), select(eta.refracts, nx, dx),
          select(eta.refracts, ny, dy), select(eta.refracts, nz, dz)};
}

// Intersect, clip, refract (refracts false: the surface does not refract any lane). The ray is
// (o, d) in the system frame, |d| = 1.
template <class V>
EYETRACE_KERNEL_INLINE Moved<V> step(const Interface& f, const V& ox, const V& oy, const V& oz, const V& dx,
                                     const V& dy, const V& dz, bool refracts, const Eta<V>& eta) {
  const V lz = oz - f.z;
  const Hit<V> hit = intersect(f.c, f.k, f.kc, f.plane, ox, oy, lz, dx, dy, dz, kBehindTolerance_mm);
  const V px = ox + hit.t * dx, py = oy + hit.t * dy, pz = lz + hit.t * dz;
  // Not inside (NaN included) is outside.
  const Mask<V> inside = px * px + py * py <= f.sd2;
  const double outside = code(f.role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted);
  V status = select(hit.hit, select(inside, V(kOk), V(outside)), V(code(TraceStatus::Missed)));
  if (!refracts) return {status, px, py, pz + f.z, dx, dy, dz};

  // Gradient of c(x^2 + y^2 + k z^2) - 2z, halved.
  const Refracted<V> r = refract(f.c * px, f.c * py, f.kc * pz - 1.0, dx, dy, dz, status, eta);
  return {r.status, px, py, pz + f.z, r.dx, r.dy, r.dz};
}

// ---- Indices at a wavelength -------------------------------------------------------------------

// The wavelength a per-ray trace uses: lambda clamped to the laws' range; NaN -> the compiled one.
template <class V>
V clamp_wavelength(const V& lambda, double compiled_nm) {
  const V clamped = select(lambda >= kMinWavelength_nm,
                           select(lambda <= kMaxWavelength_nm, lambda, V(kMaxWavelength_nm)), V(kMinWavelength_nm));
  return select(lambda == lambda, clamped, V(compiled_nm));
}

// Medium::index_at, per lane: the weights are herzberger_weights(lambda) when the law needs them.
template <class V>
V medium_index(const MediumLaw& m, const V& lambda, const std::array<V, 4>& w) {
  const V n = (m.index + dispersion::evaluate(m.dispersion, lambda, w)) - m.at_reference;
  return select(lambda == m.reference_nm, V(m.index), n);
}

template <class V>
V side_index(const Interface::Side& side, const MediumLaw* laws, const V& lambda, const std::array<V, 4>& w) {
  return side.law < 0 ? V(side.index) : medium_index(laws[side.law], lambda, w);
}

// The surface's refraction for the lanes, going Forward or in reverse. Per-ray wavelength:
// n holds, per lane, the index of the medium the ray is in and becomes that of the medium it
// enters; eta = n_from / n_to is the quotient CompiledSystem computes at the compiled wavelength,
// so a lane's bits equal those of a system compiled at its wavelength. Returns false when no
// lane refracts (the surface is a stop or the image, or its indices are equal).
template <bool Forward, bool PerRayWavelength, class V>
EYETRACE_KERNEL_INLINE bool refraction_at(const Interface& f, const MediumLaw* laws, const V& lambda,
                                          const std::array<V, 4>& w, V& n, Eta<V>& eta) {
  if constexpr (!PerRayWavelength) {
    const double e = Forward ? f.eta_forward : f.eta_reverse;
    if (e == 1.0) return false;
    eta = uniform_eta<V>(e);
    return true;
  } else {
    const Interface::Side& from = Forward ? f.before : f.after;
    const Interface::Side& to = Forward ? f.after : f.before;
    const V n_from = from.law < 0 ? V(from.index) : n;
    n = to.law >= 0 && to.law == from.law ? n_from : side_index(to, laws, lambda, w);
    if (f.role != SurfaceRole::Refract) return false;
    if (from.law < 0 && to.law < 0) {  // the same quotient at every wavelength
      const double e = Forward ? f.eta_forward_any : f.eta_reverse_any;
      if (e == 1.0) return false;
      eta = uniform_eta<V>(e);
      return true;
    }
    // Into air (the cornea of a reverse trace) n_from / 1 is n_from exactly: one division less.
    eta = eta_of(to.law < 0 && to.index == 1.0 ? n_from : n_from / n);
    return true;
  }
}

}  // namespace
}  // namespace eyetrace::optics::kernel
