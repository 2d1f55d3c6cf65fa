// The hot path of the eye camera: one loop over a flat interface array, with the ray-conic
// intersection inlined and vector Snell refraction. No allocation, no exceptions, no virtual
// calls per ray.
#include "optics/sequential_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace eyetrace::optics {

const char* to_string(TraceStatus status) {
  switch (status) {
    case TraceStatus::Ok: return "ok";
    case TraceStatus::Missed: return "missed";
    case TraceStatus::Vignetted: return "vignetted";
    case TraceStatus::StopBlocked: return "stop blocked";
    case TraceStatus::TotalInternalReflection: return "total internal reflection";
  }
  return "?";
}

CompiledSystem::CompiledSystem(const Prescription& p) {
  validate(p);
  const std::vector<double> z = p.vertex_z_mm();
  interfaces_.reserve(p.surfaces.size());
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const Surface& s = p.surfaces[i];
    Interface f;
    f.z = z[i];
    f.c = s.profile.is_flat() ? 0.0 : s.profile.curvature;
    f.k = 1.0 + s.profile.conic;
    f.sd2 = s.limited() ? s.semi_diameter_mm * s.semi_diameter_mm : std::numeric_limits<double>::infinity();
    f.n_before = p.index_before(static_cast<int>(i));
    f.n_after = s.index_after;
    // Stops and the image do not refract; eta == 1 also skips equal-index interfaces.
    const bool refracts = s.role == SurfaceRole::Refract;
    f.eta_forward = refracts ? f.n_before / f.n_after : 1.0;
    f.eta_reverse = refracts ? f.n_after / f.n_before : 1.0;
    f.role = s.role;
    interfaces_.push_back(f);
  }
  stop_index_ = p.stop_index();
}

namespace {

// Ray parameter tolerance (mm) behind the origin: lets a ray that starts exactly on a surface
// (the stop lies on the anterior lens vertex, thickness 0) meet the next one at t = 0.
constexpr double kBehindTolerance = 1e-9;

}  // namespace

// Vector Snell refraction with the unnormalised surface gradient g (so the normal is never
// normalised): d' = eta d + gamma g, with gamma the root of |d'| = 1 that continues forward,
//   gamma = (-eta (g.d) - sqrt(eta^2 (g.d)^2 + |g|^2 (1 - eta^2))) / |g|^2,   g turned so g.d < 0.
// It equals the textbook eta d + (eta cos_i - cos_t) n but has one square root and one
// independent division instead of three dependent ones: the hot loop's latency chain is
// what limits the camera's ray rate. A negative radicand is total internal reflection.
TraceResult CompiledSystem::trace_range(const Ray& ray, int first, int last, glm::dvec3* points) const {
  return first <= last ? trace_impl<true>(ray, first, last, points) : trace_impl<false>(ray, first, last, points);
}

// One surface: intersect, clip, refract. Updates o, d in place only on success.
template <bool Forward>
inline TraceStatus CompiledSystem::step(const Interface& f, glm::dvec3& o, glm::dvec3& d) {
  const glm::dvec3 local(o.x, o.y, o.z - f.z);
  const ProfileHit hit = intersect_conic(f.c, f.k, local, d, kBehindTolerance);
  if (!hit.hit) return TraceStatus::Missed;
  const glm::dvec3 p = local + hit.t * d;
  if (p.x * p.x + p.y * p.y > f.sd2)
    return f.role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted;
  const double eta = Forward ? f.eta_forward : f.eta_reverse;
  if (eta != 1.0) {
    // Gradient of c(x^2 + y^2 + k z^2) - 2z, halved.
    glm::dvec3 g(f.c * p.x, f.c * p.y, f.c * f.k * p.z - 1.0);
    double gd = glm::dot(g, d);
    if (gd > 0.0) {
      g = -g;
      gd = -gd;
    }
    const double g2 = glm::dot(g, g);
    // Zero only at a conic's centre, which no true hit reaches; a hit computed there from
    // a ray origin ~1e13 mm away (round-off) would otherwise turn into NaN below.
    if (!(g2 > 0.0)) return TraceStatus::Missed;
    const double radicand = eta * eta * gd * gd + g2 * (1.0 - eta * eta);
    if (radicand < 0.0) return TraceStatus::TotalInternalReflection;
    const double gamma = (-eta * gd - std::sqrt(radicand)) * (1.0 / g2);
    d = eta * d + gamma * g;
  }
  o = glm::dvec3(p.x, p.y, p.z + f.z);
  return TraceStatus::Ok;
}

template <bool Forward>
TraceResult CompiledSystem::trace_impl(const Ray& ray, int first, int last, glm::dvec3* points) const {
  constexpr int step_dir = Forward ? 1 : -1;
  glm::dvec3 o = ray.origin;
  // Normalised once on entry so Snell's law can assume |d| = 1.
  glm::dvec3 d = ray.direction * (1.0 / std::sqrt(glm::dot(ray.direction, ray.direction)));
  for (int i = first;; i += step_dir) {
    const glm::dvec3 o_before = o, d_before = d;
    const TraceStatus status = step<Forward>(interfaces_[i], o, d);
    if (status != TraceStatus::Ok) return {status, i, {o_before, d_before}};
    if (points) points[Forward ? i - first : first - i] = o;
    if (i == last) break;
  }
  // Snell's law keeps |d| = 1 up to rounding; renormalise once so callers can rely on it.
  d *= 1.0 / std::sqrt(glm::dot(d, d));
  return {TraceStatus::Ok, last, {o, d}};
}

// The batch trace works on up to kLanes rays at once in structure-of-arrays form, one surface
// at a time. Every lane runs the same branch-free arithmetic as step<>() (the same expressions
// in the same order, so the same bits), which lets the compiler use packed square roots and
// divisions and the CPU overlap the rays' latency chains. The cases step<>() treats specially
// (a linear intersection, a zero q, a zero gradient) are rare; a lane that meets one is marked
// and retraced afterwards by trace_range(), so the batch equals the single-ray trace bit for bit.
namespace {

constexpr std::size_t kLanes = 16;

// Lane codes, kept as doubles so every array in the surface loop has one element type.
constexpr double kAlive = 0.0;
constexpr double kRetrace = -1.0;

}  // namespace

struct CompiledSystem::Lanes {
  alignas(16) double ox[kLanes], oy[kLanes], oz[kLanes];
  alignas(16) double dx[kLanes], dy[kLanes], dz[kLanes];
  alignas(16) double code[kLanes];     // kAlive, kRetrace, or 1 + TraceStatus of the loss
  alignas(16) double surface[kLanes];  // where a lost lane was lost
};

namespace {

double code_of(TraceStatus status) { return 1.0 + static_cast<double>(status); }

}  // namespace

#if defined(__SSE2__)
// Two lanes per SSE2 register. Packed IEEE arithmetic rounds exactly as the scalar code does,
// so each lane's result is the scalar result; selects replace the scalar branches.
namespace {

using V = __m128d;
inline V splat(double x) { return _mm_set1_pd(x); }
inline V select(V mask, V a, V b) { return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b)); }
inline V sign_bit() { return splat(-0.0); }
inline V is_finite(V x) {
  return _mm_cmple_pd(_mm_andnot_pd(sign_bit(), x), splat(std::numeric_limits<double>::max()));
}

}  // namespace

template <bool Forward>
void CompiledSystem::batch_step(const Interface& f, int index, Lanes& L, std::size_t n) {
  const double eta_s = Forward ? f.eta_forward : f.eta_reverse;
  const bool refracts = eta_s != 1.0;
  const bool plane = f.c == 0.0;  // every lane takes intersect_conic()'s linear branch
  const V lost_outside =
      splat(code_of(f.role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted));
  const V missed = splat(code_of(TraceStatus::Missed)), tir = splat(code_of(TraceStatus::TotalInternalReflection));
  const V alive = splat(kAlive), retrace = splat(kRetrace), zero = _mm_setzero_pd();
  const V c = splat(f.c), k = splat(f.k), fz = splat(f.z), eta = splat(eta_s), two = splat(2.0), one = splat(1.0);
  const V one_minus_eta2 = splat(1.0 - eta_s * eta_s), eta2 = splat(eta_s * eta_s);
  const V kc = splat(f.k * f.c), ck = splat(f.c * f.k);
  for (std::size_t j = 0; j < n; j += 2) {
    const V ox = _mm_load_pd(L.ox + j), oy = _mm_load_pd(L.oy + j), oz = _mm_load_pd(L.oz + j);
    const V dx = _mm_load_pd(L.dx + j), dy = _mm_load_pd(L.dy + j), dz = _mm_load_pd(L.dz + j);
    const V lz = _mm_sub_pd(oz, fz);
    // intersect_conic(), quadratic branch, term for term.
    const V a = _mm_mul_pd(
        c, _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(_mm_mul_pd(k, dz), dz)));
    const V b = _mm_sub_pd(_mm_mul_pd(c, _mm_add_pd(_mm_add_pd(_mm_mul_pd(ox, dx), _mm_mul_pd(oy, dy)),
                                                    _mm_mul_pd(_mm_mul_pd(k, lz), dz))),
                           dz);
    const V ff = _mm_sub_pd(_mm_mul_pd(c, _mm_add_pd(_mm_add_pd(_mm_mul_pd(ox, ox), _mm_mul_pd(oy, oy)),
                                                     _mm_mul_pd(_mm_mul_pd(k, lz), lz))),
                            _mm_mul_pd(two, lz));
    const V disc = _mm_sub_pd(_mm_mul_pd(b, b), _mm_mul_pd(a, ff));
    const V has_roots = _mm_cmpge_pd(disc, zero);
    const V root = _mm_sqrt_pd(_mm_and_pd(has_roots, disc));  // >= +0: copysign is an or
    const V q = _mm_xor_pd(sign_bit(), _mm_add_pd(b, _mm_or_pd(root, _mm_and_pd(sign_bit(), b))));
    const V linear = _mm_cmpeq_pd(a, zero);
    V special = _mm_or_pd(linear, _mm_and_pd(has_roots, _mm_cmpeq_pd(q, zero)));
    const V tq = _mm_div_pd(ff, q), ta = _mm_div_pd(q, a);
    const V swap = _mm_cmplt_pd(ta, tq);
    V t0 = select(swap, ta, tq), t1 = select(swap, tq, ta);
    V crosses = has_roots;
    if (plane) {  // the linear branch: one crossing, none for a ray parallel to the plane
      const V tl = _mm_div_pd(_mm_xor_pd(sign_bit(), ff), _mm_mul_pd(two, b));
      t0 = select(linear, tl, t0), t1 = select(linear, tl, t1);
      crosses = select(linear, _mm_cmpneq_pd(b, zero), has_roots);
      special = _mm_andnot_pd(linear, special);
    }
    const V tol = splat(-kBehindTolerance), sheet = splat(-1e-9);
    const V ok0 = _mm_and_pd(_mm_and_pd(is_finite(t0), _mm_cmpge_pd(t0, tol)),
                             _mm_cmpge_pd(_mm_sub_pd(one, _mm_mul_pd(kc, _mm_add_pd(lz, _mm_mul_pd(t0, dz)))), sheet));
    const V ok1 = _mm_and_pd(_mm_and_pd(is_finite(t1), _mm_cmpge_pd(t1, tol)),
                             _mm_cmpge_pd(_mm_sub_pd(one, _mm_mul_pd(kc, _mm_add_pd(lz, _mm_mul_pd(t1, dz)))), sheet));
    const V hit = _mm_and_pd(crosses, _mm_or_pd(ok0, ok1));
    const V t = select(ok0, t0, t1);
    const V px = _mm_add_pd(ox, _mm_mul_pd(t, dx)), py = _mm_add_pd(oy, _mm_mul_pd(t, dy));
    const V pz = _mm_add_pd(lz, _mm_mul_pd(t, dz));
    const V inside = _mm_cmple_pd(_mm_add_pd(_mm_mul_pd(px, px), _mm_mul_pd(py, py)), splat(f.sd2));
    V next = select(hit, select(inside, alive, lost_outside), missed);
    V nx = dx, ny = dy, nz = dz;
    if (refracts) {  // step<>()'s refraction
      V gx = _mm_mul_pd(c, px), gy = _mm_mul_pd(c, py), gz = _mm_sub_pd(_mm_mul_pd(ck, pz), one);
      V gd = _mm_add_pd(_mm_add_pd(_mm_mul_pd(gx, dx), _mm_mul_pd(gy, dy)), _mm_mul_pd(gz, dz));
      const V flip = _mm_and_pd(_mm_cmpgt_pd(gd, zero), sign_bit());
      gx = _mm_xor_pd(gx, flip), gy = _mm_xor_pd(gy, flip), gz = _mm_xor_pd(gz, flip), gd = _mm_xor_pd(gd, flip);
      const V g2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(gx, gx), _mm_mul_pd(gy, gy)), _mm_mul_pd(gz, gz));
      const V radicand = _mm_add_pd(_mm_mul_pd(_mm_mul_pd(eta2, gd), gd), _mm_mul_pd(g2, one_minus_eta2));
      const V refracted = _mm_cmpge_pd(radicand, zero);
      const V gamma = _mm_mul_pd(
          _mm_sub_pd(_mm_mul_pd(_mm_xor_pd(sign_bit(), eta), gd), _mm_sqrt_pd(_mm_and_pd(refracted, radicand))),
          _mm_div_pd(one, g2));
      const V refract_code = select(_mm_cmpgt_pd(g2, zero), select(refracted, alive, tir), retrace);
      next = select(_mm_cmpeq_pd(next, alive), refract_code, next);
      nx = _mm_add_pd(_mm_mul_pd(eta, dx), _mm_mul_pd(gamma, gx));
      ny = _mm_add_pd(_mm_mul_pd(eta, dy), _mm_mul_pd(gamma, gy));
      nz = _mm_add_pd(_mm_mul_pd(eta, dz), _mm_mul_pd(gamma, gz));
    }
    next = select(special, retrace, next);
    const V code = _mm_load_pd(L.code + j);
    const V was_alive = _mm_cmpeq_pd(code, alive);
    const V moves = _mm_and_pd(was_alive, _mm_cmpeq_pd(next, alive));
    _mm_store_pd(L.code + j, select(was_alive, next, code));
    _mm_store_pd(L.surface + j, select(_mm_andnot_pd(moves, was_alive), splat(index), _mm_load_pd(L.surface + j)));
    _mm_store_pd(L.ox + j, select(moves, px, ox));
    _mm_store_pd(L.oy + j, select(moves, py, oy));
    _mm_store_pd(L.oz + j, select(moves, _mm_add_pd(pz, fz), oz));
    _mm_store_pd(L.dx + j, select(moves, nx, dx));
    _mm_store_pd(L.dy + j, select(moves, ny, dy));
    _mm_store_pd(L.dz + j, select(moves, nz, dz));
  }
}
#else
// Without SSE2 each lane runs step<>() itself.
template <bool Forward>
void CompiledSystem::batch_step(const Interface& f, int index, Lanes& L, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    if (L.code[j] != kAlive) continue;
    glm::dvec3 o(L.ox[j], L.oy[j], L.oz[j]), d(L.dx[j], L.dy[j], L.dz[j]);
    const TraceStatus status = step<Forward>(f, o, d);
    if (status != TraceStatus::Ok) {
      L.code[j] = code_of(status), L.surface[j] = index;
      continue;
    }
    L.ox[j] = o.x, L.oy[j] = o.y, L.oz[j] = o.z, L.dx[j] = d.x, L.dy[j] = d.y, L.dz[j] = d.z;
  }
}
#endif

void CompiledSystem::trace_range_batch(const Ray* rays, TraceResult* results, std::size_t count, int first,
                                       int last) const {
  for (std::size_t base = 0; base < count; base += kLanes)
    trace_lanes(rays + base, results + base, std::min(kLanes, count - base), first, last);
}

void CompiledSystem::trace_lanes(const Ray* rays, TraceResult* results, std::size_t n, int first, int last) const {
  Lanes L;
  for (std::size_t j = 0; j < n; ++j) {
    const glm::dvec3 d = rays[j].direction * (1.0 / std::sqrt(glm::dot(rays[j].direction, rays[j].direction)));
    L.ox[j] = rays[j].origin.x, L.oy[j] = rays[j].origin.y, L.oz[j] = rays[j].origin.z;
    L.dx[j] = d.x, L.dy[j] = d.y, L.dz[j] = d.z;
    L.code[j] = kAlive, L.surface[j] = -1.0;
  }
  // A padding lane (odd n) starts lost, so nothing it computes is used.
  for (std::size_t j = n; j < kLanes; ++j) {
    L.ox[j] = L.oy[j] = L.oz[j] = L.dx[j] = L.dy[j] = 0.0, L.dz[j] = 1.0;
    L.code[j] = code_of(TraceStatus::Missed), L.surface[j] = -1.0;
  }
  const bool forward = first <= last;
  for (int i = first;; i += forward ? 1 : -1) {
    const std::size_t even = (n + 1) & ~std::size_t(1);
    if (forward)
      batch_step<true>(interfaces_[i], i, L, even);
    else
      batch_step<false>(interfaces_[i], i, L, even);
    if (i == last) break;
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (L.code[j] == kRetrace) {
      results[j] = trace_range(rays[j], first, last);
      continue;
    }
    const glm::dvec3 o(L.ox[j], L.oy[j], L.oz[j]);
    glm::dvec3 d(L.dx[j], L.dy[j], L.dz[j]);
    if (L.code[j] == kAlive) {
      d *= 1.0 / std::sqrt(glm::dot(d, d));
      results[j] = {TraceStatus::Ok, last, {o, d}};
    } else {
      results[j] = {static_cast<TraceStatus>(static_cast<int>(L.code[j]) - 1), static_cast<int>(L.surface[j]), {o, d}};
    }
  }
}

}  // namespace eyetrace::optics
