// The step through one placed surface (placed_surface.h: a biconic, a tilted or decentred
// surface, a phase plate) for a lane type V, beside the conic kernel's step (trace_kernel.h):
// into the surface's frame, intersect (the conic kernel's closed form, or the biconic's lane
// iteration of biconic_kernel.h with the bracketed search for the lanes it defers), clip, refract
// with the kernel's refract(), and back. V = double for one ray (CompiledSystem::trace_one),
// V = an xsimd batch for a block of rays (batch_kernel.h): the same arithmetic in the same order
// per lane, so a lane has the one-ray trace's bits. A surface with a phase plate is stepped at
// V = double only: the plate's Zernike sum is evaluated one ray at a time, and the batch takes
// such a surface lane by lane, in the baseline build (batch_kernel.h: plate_surface_lanes).
//
// Internal to the optics library: included by sequential_trace.cpp and batch_kernel.h.
#pragma once

#include <cstddef>
#include <type_traits>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "optics/biconic_kernel.h"
#include "optics/placed_surface.h"

namespace eyetrace::optics::kernel {
namespace {

using trace_detail::PlacedSurface;

template <class V>
struct Vec3 {
  V x, y, z;
};

// m (x, y, z) for glm's column-major m, summed in glm's order.
template <class V>
EYETRACE_KERNEL_INLINE Vec3<V> rotate(const glm::dmat3& m, const V& x, const V& y, const V& z) {
  return {m[0][0] * x + m[1][0] * y + m[2][0] * z, m[0][1] * x + m[1][1] * y + m[2][1] * z,
          m[0][2] * x + m[1][2] * y + m[2][2] * z};
}

template <class V>
struct PlacedHit {
  Mask<V> hit;
  V t;               // where hit
  Mask<V> diverged;  // not hit because the biconic's iteration gave up
};

// The lanes the biconic's first stage deferred, one at a time through the bracketed search: what
// intersect_biconic gives one ray.
template <class V>
PlacedHit<V> resolve_deferred(const BiconicTerms& s, const Vec3<V>& o, const Vec3<V>& d, const BiconicHit<V>& h) {
  using L = Lanes<V>;
  double ox[L::size], oy[L::size], oz[L::size], dx[L::size], dy[L::size], dz[L::size];
  double hit[L::size], t[L::size], diverged[L::size], deferred[L::size];
  L::store(o.x, ox), L::store(o.y, oy), L::store(o.z, oz), L::store(d.x, dx), L::store(d.y, dy), L::store(d.z, dz);
  L::store(select(h.hit, V(1.0), V(0.0)), hit), L::store(h.t, t),
      L::store(select(h.deferred, V(1.0), V(0.0)), deferred);
  for (std::size_t j = 0; j < L::size; ++j) {
    diverged[j] = 0.0;
    if (deferred[j] == 0.0) continue;
    const ProfileHit r = intersect_biconic_bracketed(s, ox[j], oy[j], oz[j], dx[j], dy[j], dz[j], kBehindTolerance_mm);
    hit[j] = r.hit ? 1.0 : 0.0, t[j] = r.hit ? r.t : 0.0, diverged[j] = r.diverged ? 1.0 : 0.0;
  }
  return {L::load(hit) != 0.0, L::load(t), L::load(diverged) != 0.0};
}

// The first crossing of the ray (local frame) with the surface's profile: the conic kernel's
// intersection with its root choice, or the biconic's (biconic_surface.cpp, intersect_biconic),
// which iterates only the lanes in `active` (the others' results are not used).
template <class V>
EYETRACE_KERNEL_INLINE PlacedHit<V> intersect_placed(const PlacedSurface& s, const Vec3<V>& o, const Vec3<V>& d,
                                                     const Mask<V>& active) {
  const Mask<V> none = active & !active;
  if (s.profile.kind != ProfileKind::Biconic) {
    const Hit<V> h = intersect(s.c, s.k, s.kc, s.plane, o.x, o.y, o.z, d.x, d.y, d.z, kBehindTolerance_mm);
    return {h.hit, h.t, none};
  }
  const BiconicHit<V> h = intersect_biconic(s.biconic, o.x, o.y, o.z, d.x, d.y, d.z, kBehindTolerance_mm, active);
  if (!any(h.deferred)) return {h.hit, h.t, none};
  return resolve_deferred(s.biconic, o, d, h);
}

// The surface's gradient at the local point p, oriented as the conic kernel's: (c x, c y,
// k c z - 1) for a conic, (dz/dx, dz/dy, -1) for a biconic (valid false beyond its rim).
template <class V>
EYETRACE_KERNEL_INLINE Gradient<V> placed_gradient(const PlacedSurface& s, const Vec3<V>& p) {
  if (s.profile.kind == ProfileKind::Biconic) return biconic_gradient(s.biconic, p.x, p.y);
  return {Mask<V>(true), s.c * p.x, s.c * p.y, s.kc * p.z - 1.0};
}

// The kernel's refract() with the gradient g at the hit; where g is not valid (beyond a
// biconic's rim, where the slope is infinite) the lane is Missed, as refract() reports a
// non-finite gradient.
template <class V>
EYETRACE_KERNEL_INLINE Refracted<V> refract_at(const Gradient<V>& g, const Vec3<V>& d, const V& status,
                                               const Eta<V>& eta) {
  const V missed(code(TraceStatus::Missed));
  return refract(g.x, g.y, g.z, d.x, d.y, d.z, select(g.valid | (status != kOk), status, missed), eta);
}

// The ray (o, d) (system frame, |d| = 1) through surface s of the compiled system: sd2 =
// semi-diameter squared (+inf when unlimited), role decides whether an outside hit is
// StopBlocked or Vignetted; refracts false passes every lane on unbent, else Snell with eta
// (lanes with eta.refracts false go on as they came). n_to is the index of the medium the ray
// leaves into, which a plate's rule needs. A ray outside the plate's disc is lost as outside
// the aperture; one the plate bends beyond grazing is reported as TotalInternalReflection.
// Only the lanes in `active` are iterated by a biconic; the others' results are not used.
template <class V>
EYETRACE_KERNEL_INLINE Moved<V> placed_step(const PlacedSurface& s, double sd2, SurfaceRole role, const V& ox,
                                            const V& oy, const V& oz, const V& dx, const V& dy, const V& dz,
                                            bool refracts, const Eta<V>& eta, const V& n_to, const Mask<V>& active) {
  const Vec3<V> ol = rotate(s.local_from_system, ox - s.origin.x, oy - s.origin.y, oz - s.origin.z);
  const Vec3<V> dl = rotate(s.local_from_system, dx, dy, dz);
  const PlacedHit<V> hit = intersect_placed(s, ol, dl, active);
  const Vec3<V> pl{ol.x + hit.t * dl.x, ol.y + hit.t * dl.y, ol.z + hit.t * dl.z};
  // Not inside (NaN included) is outside: the aperture is centred on the surface's own axis.
  const Mask<V> inside = pl.x * pl.x + pl.y * pl.y <= sd2;
  const double outside = code(role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted);
  V status = select(hit.hit, select(inside, V(kOk), V(outside)),
                    select(hit.diverged, V(code(TraceStatus::NoConvergence)), V(code(TraceStatus::Missed))));
  const Vec3<V> pr = rotate(s.system_from_local, pl.x, pl.y, pl.z);
  const V px = pr.x + s.origin.x, py = pr.y + s.origin.y, pz = pr.z + s.origin.z;
  const bool bends = refracts && any(eta.refracts);

  if constexpr (std::is_same_v<V, double>) {
    if (s.plate) {
      if (status == kOk && !s.plate->covers(pl.x, pl.y)) status = outside;
      glm::dvec3 out(dl.x, dl.y, dl.z);  // the local direction
      if (status == kOk && bends) {
        const Refracted<V> r = refract_at(placed_gradient(s, pl), dl, status, eta);
        status = r.status, out = {r.dx, r.dy, r.dz};
      }
      // A plate lies only on a flat surface (validate), where n d_t is the same on both sides.
      if (status == kOk && !trace_detail::bend_by_plate(*s.plate, {pl.x, pl.y, pl.z}, n_to, out))
        status = code(TraceStatus::TotalInternalReflection);
      const Vec3<V> d_out = rotate(s.system_from_local, out.x, out.y, out.z);
      return {status, px, py, pz, d_out.x, d_out.y, d_out.z};
    }
  }
  if (!bends) return {status, px, py, pz, dx, dy, dz};
  const Refracted<V> r = refract_at(placed_gradient(s, pl), dl, status, eta);
  const Vec3<V> out = rotate(s.system_from_local, r.dx, r.dy, r.dz);
  if (eta.all || all(eta.refracts)) return {r.status, px, py, pz, out.x, out.y, out.z};
  // A lane whose two indices are equal at its wavelength goes on as it came.
  return {r.status,
          px,
          py,
          pz,
          select(eta.refracts, out.x, dx),
          select(eta.refracts, out.y, dy),
          select(eta.refracts, out.z, dz)};
}

}  // namespace
}  // namespace eyetrace::optics::kernel
