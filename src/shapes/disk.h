// pbrt-v4's "disk": an annulus (or wedge of one) in the plane z = height of object space,
// facing +z. Traced as an Embree user geometry with a double-precision ray-plane test.
#pragma once
#include <memory>
#include <vector>

#include "scene/registry.h"
#include "shapes/analytic_shape.h"

namespace eyetrace {

class Disk : public AnalyticShape {
 public:
  // phimax in degrees; 0 <= inner_radius < radius.
  Disk(const Transform& world_from_object, bool reverse_orientation, double height, double radius, double inner_radius,
       double phimax_deg);

  float area() const override { return float(area_); }
  ShapeSample sample_area(Vec2 u) const override;

 protected:
  std::optional<double> hit_object(const DRay& r, double tmin, double tmax) const override;
  void object_bounds(glm::dvec3* lo, glm::dvec3* hi) const override;

 private:
  void surface_at(glm::dvec3 p, SurfaceInteraction* si) const override;

  double height_, radius_, inner_radius_, phimax_;
  double area_;
};

// "float height" 0, "float radius" 1, "float innerradius" 0, "float phimax" 360.
const PluginSpec& disk_shape_spec();
std::vector<std::unique_ptr<Shape>> create_disk_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
