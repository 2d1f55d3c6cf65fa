// One surface of a system that is not rotationally symmetric, as the general trace path of
// sequential_trace.h reads it: its profile (conic or biconic) in its own frame, and where that
// frame sits in the system frame (surface_placement.h). The step through it (placed_kernel.h,
// for one ray or a batch of lanes) intersects, clips at the clear aperture (centred on the
// surface's own axis: a decentred stop is a decentred iris) and refracts, in double precision,
// reporting a lost ray by kind and never NaN. A surface with a phase plate (phase_plate.h) also
// clips at the plate's disc and bends the ray by it.
#pragma once

#include <cstdint>
#include <memory>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "optics/biconic_surface.h"
#include "optics/conic_surface.h"
#include "optics/phase_plate.h"
#include "optics/prescription.h"

namespace eyetrace::optics {

enum class TraceStatus : std::uint8_t;

namespace trace_detail {

struct PlacedSurface {
  // False: a conic with no placement and no plate, which the closed-form kernel traces
  // (trace_kernel.h).
  bool general = false;
  SurfaceProfile profile;
  // A conic's numbers as the conic kernel takes them (curvature, 1 + Q, their product, flat);
  // a biconic's as its own kernel does (biconic_kernel.h).
  double c = 0.0, k = 1.0, kc = 0.0;
  bool plane = true;
  BiconicTerms biconic;
  glm::dmat3 system_from_local{1.0};  // rotation; its transpose is local_from_system
  glm::dmat3 local_from_system{1.0};
  glm::dvec3 origin{0.0};                   // the local origin (the vertex) in the system frame
  std::shared_ptr<const PhasePlate> plate;  // null for none

  PlacedSurface() = default;
  PlacedSurface(const Surface& surface, double vertex_z);
};

// The plate's rule n d_t' = n d_t - grad W (phase_plate.h) at the local point pl on the local
// direction dl, which keeps the sign of its z component (the ray goes on the way it went).
// False when the new tangential part reaches unit length (or is not finite): no propagating ray
// is left (the caller reports TotalInternalReflection: it would travel along the surface, an
// evanescent wave).
bool bend_by_plate(const PhasePlate& plate, const glm::dvec3& pl, double n_to, glm::dvec3& dl);

// The optical path the plate of s adds at p (system frame, on the surface): -W (mm), 0 without a
// plate.
double plate_path_mm(const PlacedSurface& s, const glm::dvec3& p);

}  // namespace trace_detail
}  // namespace eyetrace::optics
