#include "shapes/disk.h"

#include "core/constants.h"
#include "core/error.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

Disk::Disk(const Transform& world_from_object, bool reverse_orientation, double height, double radius,
           double inner_radius, double phimax_deg)
    : AnalyticShape(world_from_object, reverse_orientation),
      height_(height),
      radius_(radius),
      inner_radius_(inner_radius),
      phimax_(std::clamp(phimax_deg, 0.0, 360.0) / 360.0 * kTwoPiDouble) {
  // An affine map scales every area in a plane by the same factor, so the world area (and
  // uniform sampling) is exact for any transform.
  area_ = 0.5 * phimax_ * (radius_ * radius_ - inner_radius_ * inner_radius_) * plane_area_scale();
}

void Disk::object_bounds(glm::dvec3* lo, glm::dvec3* hi) const {
  *lo = glm::dvec3(-radius_, -radius_, height_);
  *hi = glm::dvec3(radius_, radius_, height_);
}

std::optional<double> Disk::hit_object(const DRay& r, double tmin, double tmax) const {
  // A ray parallel to the plane never meets it (one lying in it grazes: no hit, as pbrt).
  if (r.d.z == 0.0) return std::nullopt;
  double t = (height_ - r.o.z) / r.d.z;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  double x = r.o.x + t * r.d.x, y = r.o.y + t * r.d.y;
  double dist2 = x * x + y * y;
  if (dist2 > radius_ * radius_ || dist2 < inner_radius_ * inner_radius_) return std::nullopt;
  if (phimax_ < kTwoPiDouble) {
    double phi = std::atan2(y, x);
    if (phi < 0.0) phi += kTwoPiDouble;
    if (phi > phimax_) return std::nullopt;
  }
  return t;
}

void Disk::surface_at(glm::dvec3 p, SurfaceInteraction* si) const {
  // The exact plane: t from Embree is a float, but any (x, y) with z = height is a point of
  // the plane, so the object-space point has no error (pbrt-v4 likewise); only the transform
  // to world space and the rounding to float add to p_error (set_surface).
  p.z = height_;
  double r_hit = std::sqrt(p.x * p.x + p.y * p.y);
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += kTwoPiDouble;
  // pbrt's parameterisation: u around, v from the rim (0) to the inner radius (1).
  double u = phi / phimax_;
  double v = (radius_ - r_hit) / (radius_ - inner_radius_);
  glm::dvec3 dpdu(-phimax_ * p.y, phimax_ * p.x, 0.0);
  glm::dvec3 dpdv = r_hit > 0.0 ? glm::dvec3(p.x, p.y, 0.0) * ((inner_radius_ - radius_) / r_hit) : glm::dvec3(0.0);
  set_surface(si, p, glm::dvec3(0.0, 0.0, 1.0), u, v, dpdu, dpdv);
}

ShapeSample Disk::sample_area(Vec2 u) const {
  // Uniform in area over the annulus wedge: r^2 uniform in [ri^2, r^2], phi uniform. (pbrt-v4
  // samples the full disk and ignores innerradius/phimax; this is exact for both.)
  double r2 = inner_radius_ * inner_radius_ + double(u.x) * (radius_ * radius_ - inner_radius_ * inner_radius_);
  double r = std::sqrt(r2), phi = double(u.y) * phimax_;
  return area_sample_at(glm::dvec3(r * std::cos(phi), r * std::sin(phi), height_));
}

const PluginSpec& disk_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "a disk (or annulus) in the plane z = height, facing +z",
      "—",
      {param::real("height", 0).with_unit("scene units"), param::real("radius", 1).above(0).with_unit("scene units"),
       param::real("innerradius", 0).at_least(0).with_unit("scene units").describe("below radius"),
       param::real("phimax", 360).left_open_range(0, 360).with_unit("deg"), alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_disk_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, disk_shape_spec(), "disk");
  float height = params.get_float("height");
  float radius = params.get_float("radius");
  float inner = params.get_float("innerradius");
  if (!(inner < radius)) params.fail("innerradius", fmt::format("must be in [0, radius = {}), got {}", radius, inner));
  float phimax = params.get_float("phimax");
  std::vector<std::unique_ptr<Shape>> shapes;
  auto disk = std::make_unique<Disk>(ctx.world_from_object, ctx.reverse_orientation, height, radius, inner, phimax);
  disk->set_alpha(read_alpha(ctx, params));
  shapes.push_back(std::move(disk));
  return shapes;
}

}  // namespace eyetrace
