#include "shapes/cylinder.h"

#include "core/constants.h"
#include "core/error.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

Cylinder::Cylinder(const Transform& world_from_object, bool reverse_orientation, double radius, double zmin,
                   double zmax, double phimax_deg)
    : AnalyticShape(world_from_object, reverse_orientation),
      radius_(radius),
      zmin_(zmin),
      zmax_(zmax),
      phimax_(std::clamp(phimax_deg, 0.0, 360.0) / 360.0 * kTwoPiDouble) {
  // The tube unrolls to a phimax r by (zmax - zmin) rectangle. World area exact for similarity
  // transforms (analytic_shape.h).
  area_ = phimax_ * radius_ * (zmax_ - zmin_) * area_scale();
}

void Cylinder::object_bounds(glm::dvec3* lo, glm::dvec3* hi) const {
  *lo = glm::dvec3(-radius_, -radius_, zmin_);
  *hi = glm::dvec3(radius_, radius_, zmax_);
}

bool Cylinder::cut_away(const glm::dvec3& p) const {
  if (p.z < zmin_ || p.z > zmax_) return true;
  if (phimax_ >= kTwoPiDouble) return false;
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += kTwoPiDouble;
  return phi > phimax_;
}

std::optional<double> Cylinder::hit_object(const DRay& r, double tmin, double tmax) const {
  const glm::dvec3 &o = r.o, &d = r.d;
  // (ox + t dx)^2 + (oy + t dy)^2 = r^2: a t^2 + 2 b t + c = 0 in the xy projection.
  const double a = d.x * d.x + d.y * d.y;
  // A ray along the axis never crosses the tube (one lying in the surface grazes it: no hit,
  // as pbrt-v4).
  if (!(a > 0.0) || !std::isfinite(a)) return std::nullopt;
  const double b = o.x * d.x + o.y * d.y;
  const double len_o = std::sqrt(o.x * o.x + o.y * o.y);
  const double c = (len_o - radius_) * (len_o + radius_);
  // b^2 - a c = a (r^2 - |f|^2), f the projected line's point closest to the axis (pbrt-v4's
  // form, free of the cancellation of b^2 - a c when the origin is far away).
  const double fx = o.x - (b / a) * d.x, fy = o.y - (b / a) * d.y;
  const double len_f = std::sqrt(fx * fx + fy * fy);
  const double disc = a * (radius_ - len_f) * (radius_ + len_f);
  // The open ends and the azimuth cut make the far root the first crossing for some rays.
  return first_crossing(r, a, b, c, disc, tmin, tmax, [this](const glm::dvec3& p) { return cut_away(p); });
}

void Cylinder::surface_at(glm::dvec3 p, SurfaceInteraction* si) const {
  // Project back onto the tube (t from Embree is a float): off it only by the projection's own
  // rounding, at most gamma_d(5) |p| per axis, as for the sphere.
  constexpr double kUnitD = std::numeric_limits<double>::epsilon() * 0.5;
  constexpr double kGammaD5 = 5.0 * kUnitD / (1.0 - 5.0 * kUnitD);
  const double rxy = std::sqrt(p.x * p.x + p.y * p.y);
  if (rxy > 0.0) {
    p.x *= radius_ / rxy;
    p.y *= radius_ / rxy;
  } else {
    p.x = radius_;
  }
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += kTwoPiDouble;
  // pbrt-v4's parameterisation: u around (phi / phimax), v along the axis from zmin.
  const double u = phi / phimax_, v = (p.z - zmin_) / (zmax_ - zmin_);
  const glm::dvec3 dpdu(-phimax_ * p.y, phimax_ * p.x, 0.0), dpdv(0.0, 0.0, zmax_ - zmin_);
  set_surface(si, p, glm::dvec3(p.x, p.y, 0.0), u, v, dpdu, dpdv, kGammaD5);
}

ShapeSample Cylinder::sample_area(Vec2 u) const {
  // Uniform in z and phi is uniform in area on the tube.
  const double z = zmin_ + double(u.x) * (zmax_ - zmin_), phi = double(u.y) * phimax_;
  return area_sample_at(glm::dvec3(radius_ * std::cos(phi), radius_ * std::sin(phi), z));
}

const PluginSpec& cylinder_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "an open tube about the z axis, optionally cut in azimuth",
      "— (a `zmin` above `zmax` is swapped as in pbrt-v4, but with a warning)",
      {param::real("radius", 1).above(0).with_unit("scene units"), param::real("zmin", -1).with_unit("scene units"),
       param::real("zmax", 1).with_unit("scene units"),
       param::real("phimax", 360).left_open_range(0, 360).with_unit("deg"), alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_cylinder_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, cylinder_shape_spec(), "cylinder");
  const float radius = params.get_float("radius");
  float zmin = params.get_float("zmin"), zmax = params.get_float("zmax");
  if (zmin > zmax) {
    warn(params.loc(),
         fmt::format("cylinder: \"zmin\" {} is above \"zmax\" {}; swapping them as pbrt does", zmin, zmax));
    std::swap(zmin, zmax);
  }
  if (!(zmax > zmin)) params.fail("zmax", fmt::format("the cylinder has no height: zmin = zmax = {}", zmin));
  auto cylinder = std::make_unique<Cylinder>(ctx.world_from_object, ctx.reverse_orientation, radius, zmin, zmax,
                                             params.get_float("phimax"));
  cylinder->set_alpha(read_alpha(ctx, params));
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::move(cylinder));
  return shapes;
}

}  // namespace eyetrace
