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

// Smallest t >= -t_tolerance at which the ray meets the sheet of the profile through the vertex
// (see conic_surface.cpp for why each root is taken or rejected). t_tolerance lets a ray that
// starts exactly on a surface (a stop placed on a lens vertex) meet it at t = 0.
// direction need not be normalised. Never produces NaN: a miss is hit == false.
ProfileHit intersect(const SurfaceProfile& profile, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_tolerance = 1e-9);

// Same as intersect() with the profile given as raw numbers (k = 1 + Q): the hot-path form
// used by the compiled tracer, inline so the per-surface loop has no call. Why each step is
// done this way:
//  - The implicit form F = c (x^2 + y^2 + k z^2) - 2 z has no 1/c, so planes (c = 0) and nearly
//    flat surfaces go through the same formula without loss of precision.
//  - The quadratic a t^2 + 2 b t + f = 0 is solved in the cancellation-free form
//    q = -(b + sign(b) sqrt(b^2 - a f)), t = f/q and t = q/a. The root f/q stays finite when
//    a -> 0 (a paraboloid hit by a ray parallel to its axis, or a plane), where the textbook
//    formula would divide a vanishing difference by a vanishing a.
//  - A conicoid has two sheets (hyperboloid) or two halves (sphere, ellipsoid). Solving
//    k c z^2 - 2 z + c r^2 = 0 for z gives z = (1 -+ sqrt(1 - k c^2 r^2)) / (k c); the sag
//    formula, i.e. the part containing the vertex, is the '-' branch, on which
//    1 - k c z = +sqrt(...) >= 0. The far sheet of a hyperboloid and the far half of a sphere or
//    ellipsoid have 1 - k c z <= 0. So a root lies on the physical surface iff 1 - k c z >= 0.
//  - Of the roots on that branch the first one along the ray (smallest t >= -t_tolerance) is
//    taken: a sequential ray meets each surface once, at its first physical crossing; a root
//    behind the origin would mean travelling backwards.
inline ProfileHit intersect_conic(double c, double k, const glm::dvec3& o, const glm::dvec3& d, double t_tolerance) {
  const double a = c * (d.x * d.x + d.y * d.y + k * d.z * d.z);
  const double b = c * (o.x * d.x + o.y * d.y + k * o.z * d.z) - d.z;
  const double f = c * (o.x * o.x + o.y * o.y + k * o.z * o.z) - 2.0 * o.z;
  double t0, t1;
  if (a == 0.0) {
    // Linear: plane, or a ray parallel to a paraboloid's axis (or a hyperboloid's
    // asymptote). One crossing, none when the ray runs parallel to a plane.
    if (b == 0.0) return {};
    t0 = t1 = -f / (2.0 * b);
  } else {
    const double disc = b * b - a * f;
    // disc < 0: the line misses the conicoid (a grazing ray that round-off pushed below 0
    // included). disc == 0 grazes: kept as a hit at the double root.
    if (!(disc >= 0.0)) return {};
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) {
      t0 = t1 = 0.0;  // b == 0 and f == 0: tangent at the ray origin
    } else {
      t0 = f / q;
      t1 = q / a;  // overflows to +-inf when a is tiny: rejected by the finiteness test
      if (t1 < t0) std::swap(t0, t1);
    }
  }
  if (std::isfinite(t0) && t0 >= -t_tolerance && 1.0 - k * c * (o.z + t0 * d.z) >= -1e-9) return {true, t0};
  if (std::isfinite(t1) && t1 >= -t_tolerance && 1.0 - k * c * (o.z + t1 * d.z) >= -1e-9) return {true, t1};
  return {};
}

// Unit surface normal at a point on the profile (local frame), oriented towards -z at the vertex,
// i.e. (0, 0, -1) there: the gradient of F = c(x^2 + y^2 + k z^2) - 2z, halved and normalised.
glm::dvec3 normal(const SurfaceProfile& profile, const glm::dvec3& point);

}  // namespace eyetrace::optics
