#include "cameras/perspective_camera.h"

#include "core/sampling.h"

namespace eyetrace {

Vec4 default_screen_window(IVec2 res, float frame) {
  if (frame <= 0.f) frame = float(res.x) / float(res.y);
  return frame > 1.f ? Vec4(-frame, frame, -1.f, 1.f) : Vec4(-1.f, 1.f, -1.f / frame, 1.f / frame);
}

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
  const Vec4& w = s_.screen_window;
  // Raster y grows downwards, screen y upwards.
  float sx = w[0] + (p.x / resolution_.x) * (w[1] - w[0]);
  float sy = w[3] - (p.y / resolution_.y) * (w[3] - w[2]);
  return Vec3(sx * tan_half_fov_, sy * tan_half_fov_, 1.f);
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
          param::reals("screenwindow")
              .size(4)
              .shown_default("shorter axis spans [−1, 1]")
              .describe("x0 x1 y0 y1 of the image plane"),
          param::real("frameaspectratio")
              .above(0)
              .describe("aspect for the default screen window instead of the image's"),
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
  std::vector<float> sw = p.get_floats("screenwindow");
  if (!sw.empty()) {
    if (sw[0] >= sw[1] || sw[2] >= sw[3]) p.fail("screenwindow", "needs x0 < x1, y0 < y1");
    s.screen_window = Vec4(sw[0], sw[1], sw[2], sw[3]);
  }
  if (p.has("frameaspectratio") && sw.empty())
    s.screen_window = default_screen_window(ctx.resolution, p.get_float("frameaspectratio"));
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
