// Exact ray-conic intersection. Why it is written this way:
//  - The implicit form F = c (x^2 + y^2 + k z^2) - 2 z (k = 1 + Q) has no 1/c, so planes (c = 0)
//    and nearly flat surfaces go through the same formula without loss of precision.
//  - The quadratic a t^2 + 2 b t + f = 0 is solved in the cancellation-free form
//    q = -(b + sign(b) sqrt(b^2 - a f)), t = f/q and t = q/a. The root f/q is the one that stays
//    finite when a -> 0 (paraboloid hit by a ray parallel to the axis, or a plane), where the
//    textbook formula would divide a vanishing difference by a vanishing a.
//  - A conicoid has two sheets (hyperboloid) or two halves (sphere, ellipsoid). Solving
//    k c z^2 - 2 z + c r^2 = 0 for z gives z = (1 -+ sqrt(1 - k c^2 r^2)) / (k c); the sag formula,
//    i.e. the part that contains the vertex, is the '-' branch, on which 1 - k c z = +sqrt(...) >= 0.
//    The other branch (the far sheet of a hyperboloid, the far half of a sphere or ellipsoid)
//    has 1 - k c z <= 0. So a root is on the physical surface exactly when 1 - k c z >= 0.
#include "optics/conic_surface.h"

#include <cmath>
#include <limits>

namespace eyetrace::optics {

SurfaceProfile SurfaceProfile::from_radius(double radius_mm, double conic) {
    if (radius_mm == 0.0) return {ProfileKind::Plane, 0.0, conic};
    return {ProfileKind::Conic, 1.0 / radius_mm, conic};
}

SurfaceProfile SurfaceProfile::from_curvature(double curvature, double conic) {
    return {curvature == 0.0 ? ProfileKind::Plane : ProfileKind::Conic, curvature, conic};
}

double SurfaceProfile::max_height() const {
    const double k = 1.0 + conic;
    if (is_flat() || k <= 0.0) return std::numeric_limits<double>::infinity();
    return 1.0 / (std::abs(curvature) * std::sqrt(k));
}

double SurfaceProfile::sag(double r2) const {
    if (is_flat()) return 0.0;
    const double k = 1.0 + conic;
    // Clamped at the rim: beyond max_height() the vertex sheet does not exist and the rim sag is
    // the closest meaningful value (validation rejects semi-diameters that reach that far).
    const double root = std::sqrt(std::fmax(0.0, 1.0 - k * curvature * curvature * r2));
    return curvature * r2 / (1.0 + root);
}

ProfileHit intersect_conic(double c, double k, const glm::dvec3& o, const glm::dvec3& d,
                           double t_tolerance) {
    // Substituting p = o + t d into F(p) = 0 gives a t^2 + 2 b t + f = 0.
    const double a = c * (d.x * d.x + d.y * d.y + k * d.z * d.z);
    const double b = c * (o.x * d.x + o.y * d.y + k * o.z * d.z) - d.z;
    const double f = c * (o.x * o.x + o.y * o.y + k * o.z * o.z) - 2.0 * o.z;

    double roots[2];
    int count = 0;
    if (a == 0.0) {
        // Linear case: plane, or a ray parallel to the axis of a paraboloid (or to an asymptote
        // of a hyperboloid). One crossing, or none when the ray runs parallel to a plane.
        if (b == 0.0) return {};
        roots[count++] = -f / (2.0 * b);
    } else {
        const double disc = b * b - a * f;
        // disc < 0: the line misses the conicoid. A grazing ray (disc == 0) is kept as a hit at
        // the double root; whether it can refract there is Snell's law's business.
        if (disc < 0.0) return {};
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        if (q == 0.0) {
            roots[count++] = 0.0;  // b == 0 and f == 0: tangent at the ray origin
        } else {
            roots[count++] = f / q;
            roots[count++] = q / a;  // may overflow to +-inf when a is tiny: filtered below
        }
    }
    if (count == 2 && roots[1] < roots[0]) std::swap(roots[0], roots[1]);

    // Take the first crossing along the ray that lies on the vertex branch: a sequential system
    // meets each surface once, at the first physical crossing. Roots behind the origin (beyond
    // the tolerance) would mean travelling backwards and are never taken.
    for (int i = 0; i < count; ++i) {
        const double t = roots[i];
        if (!std::isfinite(t) || t < -t_tolerance) continue;
        const double z = o.z + t * d.z;
        if (1.0 - k * c * z >= -1e-9) return {true, t};
    }
    return {};
}

ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin,
                     const glm::dvec3& direction, double t_tolerance) {
    const double c = profile.is_flat() ? 0.0 : profile.curvature;
    return intersect_conic(c, 1.0 + profile.conic, origin, direction, t_tolerance);
}

glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& p) {
    const double c = profile.is_flat() ? 0.0 : profile.curvature;
    const glm::dvec3 g(c * p.x, c * p.y, c * (1.0 + profile.conic) * p.z - 1.0);
    return g / std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
}

}  // namespace eyetrace::optics
