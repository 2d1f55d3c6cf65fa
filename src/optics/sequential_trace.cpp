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

TraceResult CompiledSystem::trace_range(const Ray& ray, int first, int last,
                                        glm::dvec3* points) const {
    const int step = first <= last ? 1 : -1;
    const bool forward = step > 0;
    glm::dvec3 o = ray.origin;
    // Normalised once on entry so Snell's law below can assume |d| = 1.
    glm::dvec3 d = ray.direction / std::sqrt(glm::dot(ray.direction, ray.direction));
    for (int i = first;; i += step) {
        const Interface& f = interfaces_[i];
        const glm::dvec3 local(o.x, o.y, o.z - f.z);
        const ProfileHit hit = intersect_conic(f.c, f.k, local, d, kBehindTolerance);
        if (!hit.hit) return {TraceStatus::Missed, i, {o, d}};
        const glm::dvec3 p = local + hit.t * d;
        if (p.x * p.x + p.y * p.y > f.sd2)
            return {f.role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted,
                    i, {o, d}};
        const glm::dvec3 p_system(p.x, p.y, p.z + f.z);
        if (points) points[forward ? i - first : first - i] = p_system;

        const double n1 = forward ? f.n_before : f.n_after;
        const double n2 = forward ? f.n_after : f.n_before;
        if (f.role == SurfaceRole::Refract && n1 != n2) {
            // Normal from the gradient of c(x^2 + y^2 + k z^2) - 2z, turned against the ray.
            glm::dvec3 nrm(f.c * p.x, f.c * p.y, f.c * f.k * p.z - 1.0);
            nrm /= std::sqrt(nrm.x * nrm.x + nrm.y * nrm.y + nrm.z * nrm.z);
            double cos_i = -(nrm.x * d.x + nrm.y * d.y + nrm.z * d.z);
            if (cos_i < 0.0) {
                nrm = -nrm;
                cos_i = -cos_i;
            }
            const double eta = n1 / n2;
            const double cos_t2 = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
            if (cos_t2 < 0.0) return {TraceStatus::TotalInternalReflection, i, {o, d}};
            d = eta * d + (eta * cos_i - std::sqrt(cos_t2)) * nrm;
        }
        o = p_system;
        if (i == last) break;
    }
    // Snell's law keeps |d| = 1 up to rounding; renormalise once so callers can rely on it.
    d /= std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return {TraceStatus::Ok, last, {o, d}};
}

}  // namespace eyetrace::optics
