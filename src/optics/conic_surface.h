// Surface profiles of a sequential system and their exact ray intersection. A profile lives in
// its own local frame: vertex at the origin, z along the surface's axis. Parameterised by
// curvature c = 1/R so a flat surface is c = 0 (no infinities) and by the conic constant Q
// (Zemax k): x^2 + y^2 + (1+Q) z^2 - 2 R z = 0. A biconic (biconic_surface.h) has a curvature
// and a conic in each of two orthogonal principal meridians, the first at axis_deg.
#pragma once

#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

namespace eyetrace::optics {

// Kind of profile. The kind is stored rather than inferred from the numbers: a biconic whose
// meridians happen to be equal is still traced by its own (iterative) intersection, and a
// rotationally symmetric profile keeps the closed-form kernel (trace_kernel.h).
enum class ProfileKind { Plane, Conic, Biconic };

struct SurfaceProfile {
  ProfileKind kind = ProfileKind::Plane;
  double curvature = 0.0;  // 1/mm; > 0 when the centre of curvature lies on the +z side
  double conic = 0.0;      // Q; 0 sphere, -1 paraboloid, < -1 hyperboloid, > 0 oblate
  // Biconic only: curvature and conic of the meridian at axis_deg + 90; axis_deg is the angle
  // of the first principal meridian (curvature, conic) from the local +x axis towards +y, in
  // [0, 180). A Plane or Conic ignores them.
  double cross_curvature = 0.0;
  double cross_conic = 0.0;
  double axis_deg = 0.0;

  static SurfaceProfile plane() { return {}; }
  // radius_mm == 0 stands for "flat" (the lens-file convention); any other value a conic.
  static SurfaceProfile from_radius(double radius_mm, double conic);
  static SurfaceProfile from_curvature(double curvature, double conic);
  // A biconic: (curvature, conic) in the meridian at axis_deg, (cross_curvature, cross_conic)
  // in the one at axis_deg + 90. Zero curvatures are flat meridians (a cylinder).
  static SurfaceProfile biconic(double curvature, double conic, double cross_curvature, double cross_conic,
                                double axis_deg);

  bool is_flat() const {
    return kind == ProfileKind::Plane || (curvature == 0.0 && (kind != ProfileKind::Biconic || cross_curvature == 0.0));
  }
  bool rotationally_symmetric() const { return kind != ProfileKind::Biconic; }
  // Paraxial curvature of the spherical equivalent: c for a conic, the mean of the two
  // meridians' curvatures for a biconic (what the scalar paraxial analysis uses).
  double mean_curvature() const;
  // Largest radial height the vertex sheet reaches in every direction: 1/(|c| sqrt(1+Q)) for a
  // closed (ellipsoidal or spherical) surface, +infinity for planes, paraboloids and
  // hyperboloids; for a biconic the smaller of its two meridians' reaches.
  double max_height() const;
  // Axial sag z(r^2) of the vertex sheet along the first principal meridian (for a conic, in
  // every direction). Stable for c -> 0 (no 1/c). Requires r^2 within max_height()^2.
  double sag(double r2) const;
  // Axial sag z(x, y) of the vertex sheet at a point of the local xy plane; clamped at the rim
  // like sag(r2).
  double sag(double x, double y) const;
};

// One intersection of a ray with a profile, in the profile's local frame.
struct ProfileHit {
  bool hit = false;
  double t = 0.0;         // ray parameter: hit point = origin + t * direction
  bool diverged = false;  // not hit because an iterative intersection (a biconic) gave up
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
// intersection, run for one ray; a biconic is intersected by intersect_biconic of
// biconic_surface.h). t_tolerance lets a ray that starts exactly on a surface (a
// stop placed on a lens vertex) meet it at t = 0. direction need not be normalised. Never
// produces NaN: a miss is hit == false.
ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_tolerance = kBehindTolerance_mm);

// Unit surface normal at a point on the profile (local frame), oriented towards -z at the vertex,
// i.e. (0, 0, -1) there: the gradient of F = c(x^2 + y^2 + k z^2) - 2z, halved and normalised
// (a biconic: the gradient of sag(x, y) - z, biconic_surface.h).
glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& point);

// The unnormalised gradient the refraction uses, oriented as normal(): for a conic that of
// F / 2 above, for a biconic (dz/dx, dz/dy, -1). Zero (a conic's centre) or non-finite (a
// biconic's rim) gradients are for the caller to reject.
glm::dvec3 gradient(const SurfaceProfile& profile, const glm::dvec3& point);

}  // namespace eyetrace::optics
