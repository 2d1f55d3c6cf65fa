// Base for the quadrics Embree cannot trace natively (sphere, disk): registers an Embree
// user geometry whose callbacks run the shape's own ray test in object space, in double
// precision, and holds the object/world transforms both ways in double.
#pragma once
#include <cmath>
#include <optional>
#include <utility>

#include "core/shape.h"
#include "core/transform.h"
#include "shapes/shape_alpha.h"

namespace eyetrace {

struct DRay {
  glm::dvec3 o, d;
};

class AnalyticShape : public Shape {
 public:
  AnalyticShape(const Transform& world_from_object, bool reverse_orientation);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  Bounds3 bounds() const override;
  bool alpha_masked(const TextureEvalContext& ctx) const override { return alpha_.masks(ctx); }
  bool invisible() const override { return alpha_.invisible(); }
  // Recomputes the hit in object space from t (double precision) and fills it via surface_at.
  SurfaceInteraction interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3 ng) const override;

  // Smallest t in (tmin, tmax) where the ray (given in the space the geometry lives in,
  // `d` not necessarily unit) meets the surface, skipping crossings its alpha cuts out
  // (shape_alpha.h); public for tests.
  std::optional<double> hit(const Vec3& o, const Vec3& d, double tmin, double tmax) const;
  void set_alpha(const ShapeAlpha& alpha) { alpha_ = alpha; }
  // Whether the transform is a similarity (rotation, uniform scale, mirror, translation),
  // under which uniform area sampling in object space stays uniform in world space.
  bool is_similarity() const { return is_similarity_; }

 protected:
  virtual std::optional<double> hit_object(const DRay& r, double tmin, double tmax) const = 0;
  // Object-space box around the surface.
  virtual void object_bounds(glm::dvec3* lo, glm::dvec3* hi) const = 0;
  // Position, normal, uv and tangents of the object-space surface point p (on the surface).
  virtual void surface_at(glm::dvec3 p, SurfaceInteraction* si) const = 0;
  // Stores object-space p, outward normal n, (u, v) clamped to [0, 1] and tangents in world space.
  // p may be off the exact surface by p_rel_error |p| per axis (object space, double); p_error
  // gets the world-space bound of the float p (see point_error).
  void set_surface(SurfaceInteraction* si, const glm::dvec3& p, const glm::dvec3& n, double u, double v,
                   const glm::dvec3& dpdu, const glm::dvec3& dpdv, double p_rel_error = 0.0) const;
  // The area sample at object-space surface point p: its world point, error, normal and uv
  // from surface_at, with density 1 / area() (the quadrics sample uniformly in area).
  ShapeSample area_sample_at(const glm::dvec3& p) const;
  // The first crossing in (tmin, tmax) of a quadric whose crossings solve a t^2 + 2 b t + c = 0,
  // given disc = b^2 - a c computed without cancellation by the caller (pbrt-v4's form: from
  // the line's point closest to the axis or centre): q = -(b + sign(b) sqrt(disc)) adds two
  // numbers of one sign, so the roots q / a and c / q (Vieta) keep every digit where the
  // textbook (-b + sqrt) / a loses the near root when b^2 >> a c. The near root first; when it
  // lies before tmin or its point is cut away (a partial shape, an open end), the far root is
  // the first surface the ray meets. Nothing when disc < 0 (a miss; a grazing ray, disc = 0,
  // touches at one point).
  template <class CutAway>
  static std::optional<double> first_crossing(const DRay& r, double a, double b, double c, double disc, double tmin,
                                              double tmax, CutAway cut_away) {
    if (disc < 0.0) return std::nullopt;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    for (double t : {t0, t1}) {
      if (t >= tmax) break;
      if (t > tmin && !cut_away(r.o + t * r.d)) return t;
    }
    return std::nullopt;
  }
  // Absolute error bound of point_to_world(p) for an object-space p off the surface by
  // p_rel_error |p|: carried through the transform, plus the transform's double rounding,
  // plus the final rounding to float.
  Vec3 point_error(const glm::dvec3& p, double p_rel_error) const;

  DRay to_object(const Vec3& o, const Vec3& d) const;
  Vec3 point_to_world(const glm::dvec3& p) const;
  Vec3 vector_to_world(const glm::dvec3& v) const;
  // Unit world normal of an object-space outward normal, flipped by ReverseOrientation.
  // (pbrt flips cross(dpdu, dpdv) by ReverseOrientation XOR handedness; the inverse
  // transpose already absorbs the handedness, so only ReverseOrientation remains.)
  Vec3 normal_to_world(const glm::dvec3& n) const;
  // Fills wo/time and guarantees non-degenerate tangents (poles, disk centre).
  void finish(const Ray& ray, float t, SurfaceInteraction* si) const;
  // Factor by which object-space areas grow in world space, exact for a similarity; else
  // the approximation |det|^(2/3).
  double area_scale() const { return area_scale_; }
  // Exact area factor for the plane z = const (any affine transform).
  double plane_area_scale() const;

  ShapeAlpha alpha_;
  glm::dmat4 world_from_object_, object_from_world_;
  glm::dmat3 normal_from_object_;  // inverse transpose of the linear part
  bool reverse_orientation_;
  double area_scale_ = 1.0;
  bool is_similarity_ = true;
};

}  // namespace eyetrace
