#include "cameras/perspective_camera.h"

#include "core/sampling.h"

namespace eyetrace {

PerspectiveCamera::PerspectiveCamera(const Transform& world_from_camera, IVec2 resolution, const Settings& s,
                                     const AnimatedTransform& motion)
    : world_from_camera_(world_from_camera),
      motion_(motion),
      resolution_(resolution),
      s_(s),
      tan_half_fov_(std::tan(radians(s.fov_deg) / 2.f)) {
  if (s_.screen_window == Vec4(0.f)) s_.screen_window = default_screen_window(resolution);
}

Vec3 PerspectiveCamera::camera_direction(Vec2 p) const {
  const Vec2 s = screen_from_raster(s_.screen_window, resolution_, p);
  return Vec3(s.x * tan_half_fov_, s.y * tan_half_fov_, 1.f);
}

std::optional<CameraRay> PerspectiveCamera::generate_ray(const CameraSample& cs, SampledWavelengths&) const {
  Vec3 dir = glm::normalize(camera_direction(cs.p_film));
  Vec3 origin(0.f);
  if (s_.lens_radius > 0.f) {
    // Every ray from this film point passes the point where the pinhole ray meets the plane
    // of focus z = focal_distance: that is what focusing a thin lens means.
    Vec2 lens = s_.lens_radius * sample_uniform_disk_concentric(cs.p_lens);
    Vec3 focus = dir * (s_.focal_distance / dir.z);
    origin = Vec3(lens, 0.f);
    dir = glm::normalize(focus - origin);
  }
  const float time = s_.shutter.time(cs.time);
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, time, scratch);
  Ray r{world_from_camera.point(origin), glm::normalize(world_from_camera.vector(dir)), kInfinity, time};
  return CameraRay{r, SampledSpectrum(1.f), 1.f};
}

std::string PerspectiveCamera::to_string() const {
  return fmt::format("perspective camera: fov {} deg, lens radius {}, focal distance {}", s_.fov_deg, s_.lens_radius,
                     s_.focal_distance);
}

const PluginSpec& perspective_camera_spec() {
  static const PluginSpec spec{
      "Camera",
      "a perspective projection, with an optional thin lens",
      "`perspective` as pbrt-v4. `thinlens` is another name for it; `pinhole` is the same camera with "
      "`lensradius` 0 (any other value is an error). Neither exists in pbrt-v4.",
      {
          param::real("fov", 90).open_range(0, 180).with_unit("deg").describe("across the shorter image axis"),
          param::real("lensradius", 0).at_least(0).with_unit("scene units").describe("thin-lens aperture radius"),
          param::real("focaldistance", 1e6)
              .above(0)
              .with_unit("scene units")
              .describe("distance of the plane in focus"),
          screen_window_param(),
          frame_aspect_ratio_param(),
          shutter_open_param(),
          shutter_close_param(),
      }};
  return spec;
}

static PerspectiveCamera::Settings read_settings(const CameraContext& ctx, const std::string& name) {
  // Before the table's check, which would call it an unused parameter.
  if (ctx.params.has("diffraction"))
    ctx.params.fail("diffraction", "Camera \"" + name +
                                       "\" has no pupil to diffract at (an ideal pinhole or thin lens); diffraction is "
                                       "a parameter of the eye cameras (Camera \"navarro\", \"eye\", ...)");
  const PluginParams p(ctx.params, perspective_camera_spec(), name);
  PerspectiveCamera::Settings s;
  s.fov_deg = p.get_float("fov");
  s.lens_radius = p.get_float("lensradius");
  s.focal_distance = p.get_float("focaldistance");
  s.screen_window = read_screen_window(p, ctx.resolution);
  // The shutter interval is also the film's exposure (scene_builder.cpp checks that it opens).
  s.shutter = read_shutter(p);
  return s;
}

std::unique_ptr<Camera> create_perspective_camera(const CameraContext& ctx) {
  return std::make_unique<PerspectiveCamera>(ctx.world_from_camera, ctx.resolution, read_settings(ctx, "perspective"),
                                             ctx.world_from_camera_motion);
}

std::unique_ptr<Camera> create_pinhole_camera(const CameraContext& ctx) {
  PerspectiveCamera::Settings s = read_settings(ctx, "pinhole");
  if (s.lens_radius != 0.f) ctx.params.fail("lensradius", "a pinhole camera has no lens; use \"thinlens\"");
  return std::make_unique<PerspectiveCamera>(ctx.world_from_camera, ctx.resolution, s, ctx.world_from_camera_motion);
}

std::unique_ptr<Camera> create_thinlens_camera(const CameraContext& ctx) {
  return std::make_unique<PerspectiveCamera>(ctx.world_from_camera, ctx.resolution, read_settings(ctx, "thinlens"),
                                             ctx.world_from_camera_motion);
}

}  // namespace eyetrace
