// Surface profiles: sag, reach and normal. The intersection is the sequential trace's kernel
// (trace_kernel.h, with the reasons for each root choice) run for one ray; a biconic's is the
// iteration of biconic_surface.h.
#include "optics/conic_surface.h"

#include <cmath>
#include <limits>

#include "optics/biconic_surface.h"
#include "optics/trace_kernel.h"

namespace eyetrace::optics {

SurfaceProfile SurfaceProfile::from_radius(double radius_mm, double conic) {
  if (radius_mm == 0.0) return {ProfileKind::Plane, 0.0, conic};
  return {ProfileKind::Conic, 1.0 / radius_mm, conic};
}

SurfaceProfile SurfaceProfile::from_curvature(double curvature, double conic) {
  return {curvature == 0.0 ? ProfileKind::Plane : ProfileKind::Conic, curvature, conic};
}

SurfaceProfile SurfaceProfile::biconic(double curvature, double conic, double cross_curvature, double cross_conic,
                                       double axis_deg) {
  return {ProfileKind::Biconic, curvature, conic, cross_curvature, cross_conic, axis_deg};
}

double SurfaceProfile::mean_curvature() const {
  if (kind == ProfileKind::Biconic) return 0.5 * (curvature + cross_curvature);
  return is_flat() ? 0.0 : curvature;
}

namespace {

double conic_reach(double c, double conic) {
  const double k = 1.0 + conic;
  if (c == 0.0 || k <= 0.0) return std::numeric_limits<double>::infinity();
  return 1.0 / (std::abs(c) * std::sqrt(k));
}

}  // namespace

double SurfaceProfile::max_height() const {
  if (kind == ProfileKind::Biconic)
    return std::fmin(conic_reach(curvature, conic), conic_reach(cross_curvature, cross_conic));
  if (is_flat()) return std::numeric_limits<double>::infinity();
  return conic_reach(curvature, conic);
}

double SurfaceProfile::sag(double r2) const {
  if (is_flat()) return 0.0;
  const double k = 1.0 + conic;
  // Clamped at the rim: beyond max_height() the vertex sheet does not exist and the rim sag is
  // the closest meaningful value (validation rejects semi-diameters that reach that far).
  const double root = std::sqrt(std::fmax(0.0, 1.0 - k * curvature * curvature * r2));
  return curvature * r2 / (1.0 + root);
}

double SurfaceProfile::sag(double x, double y) const {
  if (kind != ProfileKind::Biconic) return sag(x * x + y * y);
  const MeridianFrame m(axis_deg);
  const double u = m.u(x, y), v = m.v(x, y);
  // Clamped at the rim as sag(r2) is.
  const double a = (1.0 + conic) * curvature * curvature, b = (1.0 + cross_conic) * cross_curvature * cross_curvature;
  const double root = std::sqrt(std::fmax(0.0, 1.0 - a * u * u - b * v * v));
  return (curvature * u * u + cross_curvature * v * v) / (1.0 + root);
}

ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_tolerance) {
  if (profile.kind == ProfileKind::Biconic) return intersect_biconic(profile, origin, direction, t_tolerance);
  const double c = profile.is_flat() ? 0.0 : profile.curvature, k = 1.0 + profile.conic;
  const kernel::Hit<double> hit = kernel::intersect(c, k, k * c, c == 0.0, origin.x, origin.y, origin.z, direction.x,
                                                    direction.y, direction.z, t_tolerance);
  return hit.hit ? ProfileHit{true, hit.t} : ProfileHit{};
}

glm::dvec3 gradient(const SurfaceProfile& profile, const glm::dvec3& p) {
  if (profile.kind == ProfileKind::Biconic) return biconic_gradient(profile, p);
  const double c = profile.is_flat() ? 0.0 : profile.curvature;
  return {c * p.x, c * p.y, c * (1.0 + profile.conic) * p.z - 1.0};
}

glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& p) {
  const glm::dvec3 g = gradient(profile, p);
  return g / std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
}

}  // namespace eyetrace::optics
