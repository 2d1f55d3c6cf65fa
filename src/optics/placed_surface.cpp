// A placed surface's compiled numbers and its phase plate's rules (placed_surface.h); the step
// through it is placed_kernel.h's.
#include "optics/placed_surface.h"

#include <cmath>

#include <glm/matrix.hpp>

namespace eyetrace::optics::trace_detail {

PlacedSurface::PlacedSurface(const Surface& surface, double vertex_z)
    : general(!surface.profile.rotationally_symmetric() || !surface.placement.is_identity() || surface.phase_plate),
      profile(surface.profile),
      c(surface.profile.is_flat() ? 0.0 : surface.profile.curvature),
      k(1.0 + surface.profile.conic),
      kc(k * c),
      plane(c == 0.0),
      biconic(surface.profile),
      system_from_local(surface.placement.system_from_local()),
      local_from_system(glm::transpose(system_from_local)),
      origin(surface.placement.decentre_x_mm, surface.placement.decentre_y_mm, vertex_z),
      plate(surface.phase_plate) {}

bool bend_by_plate(const PhasePlate& plate, const glm::dvec3& pl, double n_to, glm::dvec3& dl) {
  const glm::dvec2 g = plate.gradient(pl.x, pl.y) * (1.0 / n_to);
  const double tx = dl.x - g.x, ty = dl.y - g.y;
  const double t2 = tx * tx + ty * ty;
  if (!(t2 < 1.0)) return false;
  dl = {tx, ty, std::copysign(std::sqrt(1.0 - t2), dl.z)};
  return true;
}

double plate_path_mm(const PlacedSurface& s, const glm::dvec3& p) {
  if (!s.plate) return 0.0;
  const glm::dvec3 pl = s.local_from_system * (p - s.origin);
  return -s.plate->wavefront_mm(pl.x, pl.y);
}

}  // namespace eyetrace::optics::trace_detail
