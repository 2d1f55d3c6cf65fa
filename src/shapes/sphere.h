// pbrt-v4's "sphere": a (possibly partial) sphere about the object-space origin, cut by
// zmin/zmax planes and by the azimuth phimax. Traced as an Embree user geometry with a
// double-precision ray-sphere test in object space.
#pragma once
#include <memory>
#include <vector>

#include "scene/registry.h"
#include "shapes/analytic_shape.h"

namespace eyetrace {

class Sphere : public AnalyticShape {
 public:
  // zmin/zmax are clamped to [-radius, radius]; phimax in degrees.
  Sphere(const Transform& world_from_object, bool reverse_orientation, double radius, double zmin, double zmax,
         double phimax_deg);

  float area() const override { return float(area_); }
  ShapeSample sample_area(Vec2 u) const override;
  const char* emitter_caveat() const override {
    return is_similarity() ? nullptr
                           : "the transform scales non-uniformly; area sampling treats the ellipsoid as if uniformly "
                             "scaled, so its density is approximate";
  }

 protected:
  std::optional<double> hit_object(const DRay& r, double tmin, double tmax) const override;
  void object_bounds(glm::dvec3* lo, glm::dvec3* hi) const override;

 private:
  bool cut_away(const glm::dvec3& p) const;
  // Surface quantities at an object-space point on the sphere.
  void surface_at(glm::dvec3 p, SurfaceInteraction* si) const override;

  double radius_, zmin_, zmax_, phimax_;
  double theta_zmin_, theta_zmax_;  // polar angles of the cut planes (theta_zmin >= theta_zmax)
  bool full_ = true;                // no cut at all: skip the cut tests
  double area_;
};

// "float radius" 1, "float zmin" -radius, "float zmax" radius, "float phimax" 360.
const PluginSpec& sphere_shape_spec();
std::vector<std::unique_ptr<Shape>> create_sphere_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
