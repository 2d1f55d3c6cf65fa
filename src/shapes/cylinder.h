// pbrt-v4's "cylinder": the open tube x^2 + y^2 = radius^2, zmin <= z <= zmax, optionally cut
// in azimuth at phimax, about the object-space z axis; no end caps (as pbrt-v4). Traced as an
// Embree user geometry with a double-precision ray-cylinder test in object space.
#pragma once
#include <memory>
#include <vector>

#include "scene/registry.h"
#include "shapes/analytic_shape.h"

namespace eyetrace {

class Cylinder : public AnalyticShape {
 public:
  // zmin < zmax; phimax in degrees.
  Cylinder(const Transform& world_from_object, bool reverse_orientation, double radius, double zmin, double zmax,
           double phimax_deg);

  float area() const override { return float(area_); }
  ShapeSample sample_area(Vec2 u) const override;
  const char* emitter_caveat() const override {
    return is_similarity() ? nullptr
                           : "the transform scales non-uniformly; area sampling treats it as if uniformly scaled, so "
                             "its density is approximate";
  }

 protected:
  std::optional<double> hit_object(const DRay& r, double tmin, double tmax) const override;
  void object_bounds(glm::dvec3* lo, glm::dvec3* hi) const override;

 private:
  void surface_at(glm::dvec3 p, SurfaceInteraction* si) const override;
  bool cut_away(const glm::dvec3& p) const;

  double radius_, zmin_, zmax_, phimax_;
  double area_;
};

// "float radius" 1, "float zmin" -1, "float zmax" 1, "float phimax" 360.
const PluginSpec& cylinder_shape_spec();
std::vector<std::unique_ptr<Shape>> create_cylinder_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
