// The hot path of the eye camera: one loop over a flat interface array, with the ray-conic
// intersection inlined and vector Snell refraction. No allocation, no exceptions, no virtual
// calls per ray.
#include "optics/sequential_trace.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

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
        f.sd2 = s.limited() ? s.semi_diameter_mm * s.semi_diameter_mm
                            : std::numeric_limits<double>::infinity();
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
TraceResult CompiledSystem::trace_range(const Ray& ray, int first, int last,
                                        glm::dvec3* points) const {
    return first <= last ? trace_impl<true>(ray, first, last, points)
                         : trace_impl<false>(ray, first, last, points);
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
TraceResult CompiledSystem::trace_impl(const Ray& ray, int first, int last,
                                       glm::dvec3* points) const {
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

void CompiledSystem::trace_range_batch(const Ray* rays, TraceResult* results, std::size_t count,
                                       int first, int last) const {
    // Surface-major order: the rays of one surface are independent, so the CPU overlaps their
    // square-root/division chains, which a single ray's trace cannot do.
    const bool forward = first <= last;
    for (std::size_t j = 0; j < count; ++j) {
        const glm::dvec3 d = rays[j].direction;
        results[j] = {TraceStatus::Ok, -1, {rays[j].origin, d * (1.0 / std::sqrt(glm::dot(d, d)))}};
    }
    for (int i = first;; i += forward ? 1 : -1) {
        const Interface& f = interfaces_[i];
        for (std::size_t j = 0; j < count; ++j) {
            TraceResult& r = results[j];
            if (r.status != TraceStatus::Ok) continue;
            const TraceStatus status = forward ? step<true>(f, r.ray.origin, r.ray.direction)
                                               : step<false>(f, r.ray.origin, r.ray.direction);
            if (status != TraceStatus::Ok) r.status = status, r.surface = i;
        }
        if (i == last) break;
    }
    for (std::size_t j = 0; j < count; ++j) {
        TraceResult& r = results[j];
        if (r.status != TraceStatus::Ok) continue;
        r.surface = last;
        r.ray.direction *= 1.0 / std::sqrt(glm::dot(r.ray.direction, r.ray.direction));
    }
}

}  // namespace eyetrace::optics
