// Where a surface sits when it is not centred on the system's axis: a decentration of its vertex
// in x and y, then a tilt about the vertex. Conventions (docs/eye-models.md, "Non-symmetric
// surfaces"): the surface's local frame has its origin at (decentre_x, decentre_y, z_vertex)
// and is turned by system_from_local = Rx(tilt_x) Ry(tilt_y), right-handed rotations about the
// system's x axis and then the turned y axis (the intrinsic x-y order of a Zemax coordinate
// break). A positive tilt_x turns the surface's axis from +z towards -y, a positive tilt_y from
// +z towards +x. The placement belongs to its surface alone: the next vertex is still its
// thickness further along the system's z axis.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace eyetrace::optics {

// Tilts are limited to (-kMaxTilt_deg, kMaxTilt_deg): beyond, a surface would face sideways.
inline constexpr double kMaxTilt_deg = 80.0;
// Decentrations are limited to kMaxDecentre_mm in x and y.
inline constexpr double kMaxDecentre_mm = 1000.0;

struct SurfacePlacement {
  double decentre_x_mm = 0.0, decentre_y_mm = 0.0;
  double tilt_x_deg = 0.0, tilt_y_deg = 0.0;

  bool is_identity() const {
    return decentre_x_mm == 0.0 && decentre_y_mm == 0.0 && tilt_x_deg == 0.0 && tilt_y_deg == 0.0;
  }
  // Rx(tilt_x) Ry(tilt_y): the columns are the local axes in the system frame.
  glm::dmat3 system_from_local() const;
};

}  // namespace eyetrace::optics
