// The rotation of a placed surface (conventions in surface_placement.h).
#include "optics/surface_placement.h"

#include <cmath>
#include <numbers>

namespace eyetrace::optics {

glm::dmat3 SurfacePlacement::system_from_local() const {
  const double ax = tilt_x_deg * std::numbers::pi / 180.0, ay = tilt_y_deg * std::numbers::pi / 180.0;
  const double cx = std::cos(ax), sx = std::sin(ax), cy = std::cos(ay), sy = std::sin(ay);
  // glm is column-major: glm::dmat3(c0, c1, c2). Rx = [[1,0,0],[0,cx,-sx],[0,sx,cx]],
  // Ry = [[cy,0,sy],[0,1,0],[-sy,0,cy]]; Rx Ry = [[cy, 0, sy], [sx sy, cx, -sx cy], [-cx sy, sx, cx cy]].
  return glm::dmat3(glm::dvec3(cy, sx * sy, -cx * sy), glm::dvec3(0.0, cx, sx), glm::dvec3(sy, -sx * cy, cx * cy));
}

}  // namespace eyetrace::optics
