// Surface profiles of a rotationally symmetric sequential system and their exact ray
// intersection. A profile lives in its own local frame: vertex at the origin, z along the optical
// axis. Parameterised by curvature c = 1/R so a flat surface is c = 0 (no infinities) and by the
// conic constant Q (Zemax k): x^2 + y^2 + (1+Q) z^2 - 2 R z = 0.
#pragma once

#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

namespace eyetrace::optics {

// Kind of profile. Only Plane and Conic exist today; an even asphere or a tilted/decentred
// surface would be a new kind with its own intersect (an iterative one for the asphere), which
// is why the kind is stored rather than inferred from c == 0.
enum class ProfileKind { Plane, Conic };

struct SurfaceProfile {
  ProfileKind kind = ProfileKind::Plane;
  double curvature = 0.0;  // 1/mm; > 0 when the centre of curvature lies on the +z side
  double conic = 0.0;      // Q; 0 sphere, -1 paraboloid, < -1 hyperboloid, > 0 oblate

  static SurfaceProfile plane() { return {}; }
  // radius_mm == 0 stands for "flat" (the lens-file convention); any other value a conic.
  static SurfaceProfile from_radius(double radius_mm, double conic);
  static SurfaceProfile from_curvature(double curvature, double conic);

  bool is_flat() const { return kind == ProfileKind::Plane || curvature == 0.0; }
  // Largest radial height the vertex sheet reaches: 1/(|c| sqrt(1+Q)) for a closed
  // (ellipsoidal or spherical) surface, +infinity for planes, paraboloids and hyperboloids.
  double max_height() const;
  // Axial sag z(r^2) of the vertex sheet. Stable for c -> 0 (no 1/c). Requires r^2 within
  // max_height()^2.
  double sag(double r2) const;
};

// One intersection of a ray with a profile, in the profile's local frame.
struct ProfileHit {
  bool hit = false;
  double t = 0.0;  // ray parameter: hit point = origin + t * direction
};

// How far behind its origin (ray parameter, mm for a unit direction) a ray may still meet a
// surface: lets a ray that starts exactly on a surface (the stop lies on the anterior lens
// vertex, thickness 0) meet the next one at t = 0.
inline constexpr double kBehindTolerance_mm = 1e-9;
// A root lies on the vertex sheet of the conic when 1 - k c z >= -kSheetTolerance (see
// trace_kernel.h): round-off in z may put a hit on the rim of a closed conic just past it.
inline constexpr double kSheetTolerance = 1e-9;

// Smallest t >= -t_tolerance at which the ray meets the sheet of the profile through the vertex
// (trace_kernel.h says why each root is taken or rejected; this is the sequential trace's own
// intersection, run for one ray). t_tolerance lets a ray that starts exactly on a surface (a
// stop placed on a lens vertex) meet it at t = 0. direction need not be normalised. Never
// produces NaN: a miss is hit == false.
ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_tolerance = kBehindTolerance_mm);

// Unit surface normal at a point on the profile (local frame), oriented towards -z at the vertex,
// i.e. (0, 0, -1) there: the gradient of F = c(x^2 + y^2 + k z^2) - 2z, halved and normalised.
glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& point);

}  // namespace eyetrace::optics
