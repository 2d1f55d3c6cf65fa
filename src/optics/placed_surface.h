// One surface of a system that is not rotationally symmetric, as the general trace path of
// sequential_trace.h reads it: its profile (conic or biconic) in its own frame, and where that
// frame sits in the system frame (surface_placement.h). step_placed intersects, clips at the
// clear aperture (centred on the surface's own axis: a decentred stop is a decentred iris) and
// refracts one ray, in double precision, reporting a lost ray by kind and never NaN. A surface
// with a phase plate (phase_plate.h) also clips at the plate's disc and bends the ray by it.
#pragma once

#include <cstdint>
#include <memory>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

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
  glm::dmat3 system_from_local{1.0};  // rotation; its transpose is local_from_system
  glm::dmat3 local_from_system{1.0};
  glm::dvec3 origin{0.0};                   // the local origin (the vertex) in the system frame
  std::shared_ptr<const PhasePlate> plate;  // null for none

  PlacedSurface() = default;
  PlacedSurface(const Surface& surface, double vertex_z);
};

// Where a ray is after a placed surface: status Ok and the hit point and new direction (system
// frame), or the reason it was lost (then p and d are the ray as it came).
struct PlacedStep {
  TraceStatus status;
  glm::dvec3 p, d;
};

// The ray (o, d) (system frame, |d| = 1) against surface s: sd2 = semi-diameter squared (+inf
// when unlimited), role decides whether an outside hit is StopBlocked or Vignetted; refracts
// false passes the ray on unbent, else Snell with eta = n_from / n_to. n_to is the index of the
// medium the ray leaves into, which the plate's rule needs. A ray outside the plate's disc is
// lost as outside the aperture; one the plate bends beyond grazing (|n d_t| >= n) is reported
// as TotalInternalReflection (it would travel along the surface: an evanescent wave).
PlacedStep step_placed(const PlacedSurface& s, double sd2, SurfaceRole role, const glm::dvec3& o, const glm::dvec3& d,
                       bool refracts, double eta, double n_to);

// The optical path the plate of s adds at p (system frame, on the surface): -W (mm), 0 without a
// plate.
double plate_path_mm(const PlacedSurface& s, const glm::dvec3& p);

}  // namespace trace_detail
}  // namespace eyetrace::optics
