// Surface profiles: sag, reach and normal. The intersection is the sequential trace's kernel
// (trace_kernel.h, with the reasons for each root choice) run for one ray.
#include "optics/conic_surface.h"

#include <cmath>
#include <limits>

#include "optics/trace_kernel.h"

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

ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_tolerance) {
  const double c = profile.is_flat() ? 0.0 : profile.curvature, k = 1.0 + profile.conic;
  const kernel::Hit<double> hit = kernel::intersect(c, k, k * c, c == 0.0, origin.x, origin.y, origin.z, direction.x,
                                                    direction.y, direction.z, t_tolerance);
  return hit.hit ? ProfileHit{true, hit.t} : ProfileHit{};
}

glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& p) {
  const double c = profile.is_flat() ? 0.0 : profile.curvature;
  const glm::dvec3 g(c * p.x, c * p.y, c * (1.0 + profile.conic) * p.z - 1.0);
  return g / std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
}

}  // namespace eyetrace::optics
