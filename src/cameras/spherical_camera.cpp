#include "cameras/spherical_camera.h"

#include <utility>

#include "lights/sphere_mapping.h"

namespace eyetrace {

Vec2 wrap_equal_area_square(Vec2 uv) {
  if (uv.x < 0.f) {
    uv = Vec2(-uv.x, 1.f - uv.y);  // mirror across u = 0 and v = 1/2
  } else if (uv.x > 1.f) {
    uv = Vec2(2.f - uv.x, 1.f - uv.y);
  }
  if (uv.y < 0.f) {
    uv = Vec2(1.f - uv.x, -uv.y);  // mirror across u = 1/2 and v = 0
  } else if (uv.y > 1.f) {
    uv = Vec2(1.f - uv.x, 2.f - uv.y);
  }
  return uv;
}

Vec3 spherical_direction(SphericalMapping mapping, Vec2 uv) {
  Vec3 d = mapping == SphericalMapping::Equirectangular ? latlong_square_to_sphere(uv)
                                                        : equal_area_square_to_sphere(wrap_equal_area_square(uv));
  std::swap(d.y, d.z);
  return glm::normalize(d);
}

SphericalCamera::SphericalCamera(const Transform& world_from_camera, IVec2 resolution, SphericalMapping mapping,
                                 const Shutter& shutter, const AnimatedTransform& motion)
    : world_from_camera_(world_from_camera),
      motion_(motion),
      resolution_(resolution),
      mapping_(mapping),
      shutter_(shutter) {}

std::optional<CameraRay> SphericalCamera::generate_ray(const CameraSample& cs, SampledWavelengths&) const {
  const Vec2 uv(cs.p_film.x / float(resolution_.x), cs.p_film.y / float(resolution_.y));
  const Vec3 dir = spherical_direction(mapping_, uv);
  const float time = shutter_.time(cs.time);
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, time, scratch);
  Ray r{world_from_camera.point(Vec3(0.f)), glm::normalize(world_from_camera.vector(dir)), kInfinity, time};
  return CameraRay{r, SampledSpectrum(1.f), 1.f};
}

std::string SphericalCamera::to_string() const {
  return fmt::format("spherical camera: {} mapping",
                     mapping_ == SphericalMapping::EqualArea ? "equal-area" : "equirectangular");
}

const PluginSpec& spherical_camera_spec() {
  static const PluginSpec spec{
      "Camera",
      "the whole sphere of directions around the camera",
      "`lensradius`, `focaldistance`, `screenwindow` and `frameaspectratio` have no effect (as in pbrt-v4, which reads "
      "and ignores them); given, they are warned about.",
      {
          param::string("mapping", "equalarea")
              .in({"equalarea", "equirectangular"})
              .describe("equal-area octahedral (centre: the camera's +y) or latitude-longitude (top row: +y)"),
          param::real("lensradius", 0).describe("no effect"),
          param::real("focaldistance", 1e30).describe("no effect"),
          param::reals("screenwindow").size(4).describe("no effect"),
          param::real("frameaspectratio").describe("no effect"),
          shutter_open_param(),
          shutter_close_param(),
      }};
  return spec;
}

std::unique_ptr<Camera> create_spherical_camera(const CameraContext& ctx) {
  const PluginParams p(ctx.params, spherical_camera_spec(), "spherical");
  for (const char* ignored : {"lensradius", "focaldistance", "screenwindow", "frameaspectratio"})
    if (p.has(ignored)) p.warn_param(ignored, "has no effect on a spherical camera (pbrt-v4 reads and ignores it too)");
  const SphericalMapping mapping =
      p.get_string("mapping") == "equirectangular" ? SphericalMapping::Equirectangular : SphericalMapping::EqualArea;
  // The shutter interval is also the film's exposure (scene_builder.cpp checks that it opens).
  return std::make_unique<SphericalCamera>(ctx.world_from_camera, ctx.resolution, mapping, read_shutter(p),
                                           ctx.world_from_camera_motion);
}

}  // namespace eyetrace
