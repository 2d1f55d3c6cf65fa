#include "shapes/sphere.h"

#include "core/constants.h"
#include "core/error.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

Sphere::Sphere(const Transform& world_from_object, bool reverse_orientation, double radius, double zmin, double zmax,
               double phimax_deg)
    : AnalyticShape(world_from_object, reverse_orientation), radius_(radius) {
  zmin_ = std::clamp(std::min(zmin, zmax), -radius, radius);
  zmax_ = std::clamp(std::max(zmin, zmax), -radius, radius);
  phimax_ = std::clamp(phimax_deg, 0.0, 360.0) / 360.0 * kTwoPiDouble;
  theta_zmin_ = std::acos(std::clamp(zmin_ / radius, -1.0, 1.0));
  theta_zmax_ = std::acos(std::clamp(zmax_ / radius, -1.0, 1.0));
  full_ = zmin_ <= -radius && zmax_ >= radius && phimax_ >= kTwoPiDouble;
  // Archimedes: a spherical zone's area is 2 pi r times its height, so a wedge of it is
  // phimax r (zmax - zmin). World area exact for similarity transforms (see header).
  area_ = phimax_ * radius_ * (zmax_ - zmin_) * area_scale();
}

void Sphere::object_bounds(glm::dvec3* lo, glm::dvec3* hi) const {
  *lo = glm::dvec3(-radius_, -radius_, zmin_);
  *hi = glm::dvec3(radius_, radius_, zmax_);
}

bool Sphere::cut_away(const glm::dvec3& p) const {
  if (full_) return false;
  if (p.z < zmin_ || p.z > zmax_) return true;
  if (phimax_ >= kTwoPiDouble) return false;
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += kTwoPiDouble;
  return phi > phimax_;
}

std::optional<double> Sphere::hit_object(const DRay& r, double tmin, double tmax) const {
  const glm::dvec3 &o = r.o, &d = r.d;
  double a = glm::dot(d, d);
  if (!(a > 0.0) || !std::isfinite(a)) return std::nullopt;
  double b = glm::dot(o, d);  // half of the textbook b: roots are (-b +- sqrt(b^2 - a c)) / a
  double len_o = glm::length(o);
  double c = (len_o - radius_) * (len_o + radius_);  // |o|^2 - r^2 without cancellation near |o| = r
  // b^2 - a c = a (r^2 - |f|^2), f = the point of the line closest to the centre (pbrt-v4's
  // form): b^2 and a c are huge and nearly equal when the origin is far from a small
  // sphere, while |f| is computed directly.
  glm::dvec3 f = o - (b / a) * d;
  double len_f = glm::length(f);
  double disc = a * (radius_ - len_f) * (radius_ + len_f);
  return first_crossing(r, a, b, c, disc, tmin, tmax, [this](const glm::dvec3& p) { return cut_away(p); });
}

void Sphere::surface_at(glm::dvec3 p, SurfaceInteraction* si) const {
  // Project back onto the surface: t from Embree is a float, so o + t d is off by ~|o| eps.
  // The projected point is off the sphere only by the projection's own rounding, at most
  // gamma_d(5) |p| per axis (pbrt-v4's bound for p * r / |p|, here in double).
  constexpr double kUnitD = std::numeric_limits<double>::epsilon() * 0.5;
  constexpr double kGammaD5 = 5.0 * kUnitD / (1.0 - 5.0 * kUnitD);
  double len = glm::length(p);
  p = len > 0.0 ? p * (radius_ / len) : glm::dvec3(0.0, 0.0, radius_);
  double phi = std::atan2(p.y, p.x);
  if (phi < 0.0) phi += kTwoPiDouble;
  double cos_theta = std::clamp(p.z / radius_, -1.0, 1.0);
  double theta = std::acos(cos_theta), sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  double rxy = std::sqrt(p.x * p.x + p.y * p.y);
  double cos_phi = rxy > 0.0 ? p.x / rxy : 1.0, sin_phi = rxy > 0.0 ? p.y / rxy : 0.0;
  double u = phi / phimax_;
  double v = (theta - theta_zmin_) / (theta_zmax_ - theta_zmin_);
  glm::dvec3 dpdu(-phimax_ * p.y, phimax_ * p.x, 0.0);
  glm::dvec3 dpdv = (theta_zmax_ - theta_zmin_) * glm::dvec3(p.z * cos_phi, p.z * sin_phi, -radius_ * sin_theta);
  set_surface(si, p, p, u, v, dpdu, dpdv, kGammaD5);
}

ShapeSample Sphere::sample_area(Vec2 u) const {
  // Uniform in z and in phi is uniform in area on a sphere (Archimedes), so this is exact
  // for partial spheres too. In world space it stays uniform under similarity transforms;
  // under a non-uniform scale the density is only approximately 1 / area (warned at load).
  double z = zmin_ + double(u.x) * (zmax_ - zmin_);
  double phi = double(u.y) * phimax_;
  double rxy = std::sqrt(std::max(0.0, radius_ * radius_ - z * z));
  return area_sample_at(glm::dvec3(rxy * std::cos(phi), rxy * std::sin(phi), z));
}

const PluginSpec& sphere_shape_spec() {
  static const PluginSpec spec{"Shape",
                               "a sphere about the origin, optionally cut in z and in azimuth",
                               "— (a `zmin` above `zmax` is swapped as in pbrt-v4, but with a warning)",
                               {param::real("radius", 1).above(0).with_unit("scene units"),
                                param::real("zmin").shown_default("−radius").with_unit("scene units"),
                                param::real("zmax").shown_default("radius").with_unit("scene units"),
                                param::real("phimax", 360).left_open_range(0, 360).with_unit("deg"), alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_sphere_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, sphere_shape_spec(), "sphere");
  float radius = params.get_float("radius");
  float zmin = params.has("zmin") ? params.get_float("zmin") : -radius;
  float zmax = params.has("zmax") ? params.get_float("zmax") : radius;
  float phimax = params.get_float("phimax");
  if (zmin > zmax) {
    warn(params.loc(), fmt::format("sphere: \"zmin\" {} is above \"zmax\" {}; swapping them as pbrt does", zmin, zmax));
    std::swap(zmin, zmax);
  }
  if (!(std::min(zmax, radius) > std::max(zmin, -radius)))
    params.fail("zmin", fmt::format("the cut [zmin, zmax] = [{}, {}] leaves nothing of a sphere of radius {}", zmin,
                                    zmax, radius));
  auto sphere = std::make_unique<Sphere>(ctx.world_from_object, ctx.reverse_orientation, radius, zmin, zmax, phimax);
  sphere->set_alpha(read_alpha(ctx, params));
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::move(sphere));
  return shapes;
}

}  // namespace eyetrace
