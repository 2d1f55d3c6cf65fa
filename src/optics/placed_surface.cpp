// The general path's step through one surface (see placed_surface.h): into the surface's frame,
// intersect (closed form for a conic, Newton for a biconic), clip, refract, and back.
#include "optics/placed_surface.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "optics/sequential_trace.h"

namespace eyetrace::optics::trace_detail {

PlacedSurface::PlacedSurface(const Surface& surface, double vertex_z)
    : general(!surface.profile.rotationally_symmetric() || !surface.placement.is_identity() || surface.phase_plate),
      profile(surface.profile),
      system_from_local(surface.placement.system_from_local()),
      local_from_system(glm::transpose(system_from_local)),
      origin(surface.placement.decentre_x_mm, surface.placement.decentre_y_mm, vertex_z),
      plate(surface.phase_plate) {}

namespace {

// The plate's rule n d_t' = n d_t - grad W (phase_plate.h) on the local direction dl, which keeps
// the sign of its z component (the ray goes on the way it went). False when the new tangential
// part reaches unit length (or is not finite): no propagating ray is left.
bool bend_by_plate(const PhasePlate& plate, const glm::dvec3& pl, double n_to, glm::dvec3& dl) {
  const glm::dvec2 g = plate.gradient(pl.x, pl.y) * (1.0 / n_to);
  const double tx = dl.x - g.x, ty = dl.y - g.y;
  const double t2 = tx * tx + ty * ty;
  if (!(t2 < 1.0)) return false;
  dl = {tx, ty, std::copysign(std::sqrt(1.0 - t2), dl.z)};
  return true;
}

}  // namespace

double plate_path_mm(const PlacedSurface& s, const glm::dvec3& p) {
  if (!s.plate) return 0.0;
  const glm::dvec3 pl = s.local_from_system * (p - s.origin);
  return -s.plate->wavefront_mm(pl.x, pl.y);
}

// Refraction is the kernel's vector Snell law (trace_kernel.h, step) with the unnormalised
// gradient g: d' = eta d + gamma g, gamma = (-eta (g.d) - sqrt(eta^2 (g.d)^2 + |g|^2 (1 -
// eta^2))) / |g|^2 with g turned so that g.d <= 0, the root that continues forward. A negative
// radicand is total internal reflection. A zero or non-finite gradient (a conic's centre, a
// biconic's rim where the slope is infinite: a ray exactly grazing the rim) is reported as
// Missed.
PlacedStep step_placed(const PlacedSurface& s, double sd2, SurfaceRole role, const glm::dvec3& o, const glm::dvec3& d,
                       bool refracts, double eta, double n_to) {
  const glm::dvec3 ol = s.local_from_system * (o - s.origin);
  const glm::dvec3 dl = s.local_from_system * d;
  const ProfileHit hit = intersect(s.profile, ol, dl, kBehindTolerance_mm);
  if (!hit.hit) return {hit.diverged ? TraceStatus::NoConvergence : TraceStatus::Missed, o, d};
  const glm::dvec3 pl = ol + hit.t * dl;
  // Not inside (NaN included) is outside: the aperture is centred on the surface's own axis.
  if (!(pl.x * pl.x + pl.y * pl.y <= sd2))
    return {role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted, o, d};
  if (s.plate && !s.plate->covers(pl.x, pl.y))
    return {role == SurfaceRole::Stop ? TraceStatus::StopBlocked : TraceStatus::Vignetted, o, d};
  const glm::dvec3 p = s.system_from_local * pl + s.origin;
  if (!refracts) {
    if (!s.plate) return {TraceStatus::Ok, p, d};
    glm::dvec3 out = dl;
    if (!bend_by_plate(*s.plate, pl, n_to, out)) return {TraceStatus::TotalInternalReflection, o, d};
    return {TraceStatus::Ok, p, s.system_from_local * out};
  }

  glm::dvec3 g = gradient(s.profile, pl);
  double gd = glm::dot(g, dl);
  if (gd > 0.0) g = -g, gd = -gd;
  const double g2 = glm::dot(g, g);
  if (!(g2 > 0.0) || !std::isfinite(g2)) return {TraceStatus::Missed, o, d};
  const double radicand = eta * eta * gd * gd + g2 * (1.0 - eta * eta);
  if (!(radicand >= 0.0)) return {TraceStatus::TotalInternalReflection, o, d};
  const double gamma = (-eta * gd - std::sqrt(radicand)) / g2;
  glm::dvec3 out = eta * dl + gamma * g;
  // A plate lies only on a flat surface (validate), where n d_t is the same on both sides.
  if (s.plate && !bend_by_plate(*s.plate, pl, n_to, out)) return {TraceStatus::TotalInternalReflection, o, d};
  return {TraceStatus::Ok, p, s.system_from_local * out};
}

}  // namespace eyetrace::optics::trace_detail
