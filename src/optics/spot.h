// Real-ray spot on the image surface for a point source, rays filling the real entrance pupil.
//
// How the pupil is filled: rays are launched through a square grid on the paraxial entrance-pupil
// plane. A coarse pass over three times the paraxial pupil radius finds where rays actually pass
// (the real pupil is shifted and distorted off axis), then a fine N x N grid over that bounding
// box is traced and every ray that reaches the image is kept. The kept rays sample the real
// entrance pupil uniformly; their number is reported.
#pragma once

#include <limits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/prescription.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {

struct SpotOptions {
  // Angle of the source from the axis in the y-z plane, |.| < 85; a positive field puts the
  // source above the axis (+y), so its image lands at -y.
  double field_deg = 0.0;
  // Distance of the point source from the entrance-pupil centre, metres; +inf = at infinity.
  double object_distance_m = std::numeric_limits<double>::infinity();
  int grid = 64;  // fine grid size across the pupil's bounding box
};

struct SpotResult {
  double field_deg = 0.0;
  int rays = 0;                // rays that reached the image surface
  int rays_launched = 0;       // rays of the fine grid
  double rms_radius_um = 0.0;  // about the centroid (3D distances on the image surface); 0 if rays == 0
  // Radius about the centroid that holds half the rays (same distances): unlike the RMS radius
  // it follows the dense core of the spot, not its sparse flare.
  double ee50_radius_um = 0.0;
  glm::dvec3 centroid_mm{0.0};
  std::vector<glm::dvec2> points_um;  // (x, y) of every ray relative to the centroid, micrometres
};

// Throws OpticsError for an invalid field or distance. A spot with no ray through (everything
// vignetted) is returned with rays == 0.
SpotResult trace_spot(const Prescription& prescription, const SpotOptions& options);

}  // namespace eyetrace::optics
