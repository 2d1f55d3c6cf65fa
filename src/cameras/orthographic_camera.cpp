#include "cameras/orthographic_camera.h"

#include "core/sampling.h"

namespace eyetrace {

OrthographicCamera::OrthographicCamera(const Transform& world_from_camera, IVec2 resolution, const Settings& s,
                                       const AnimatedTransform& motion)
    : world_from_camera_(world_from_camera), motion_(motion), resolution_(resolution), s_(s) {
  if (s_.screen_window == Vec4(0.f)) s_.screen_window = default_screen_window(resolution);
}

std::optional<CameraRay> OrthographicCamera::generate_ray(const CameraSample& cs, SampledWavelengths&) const {
  const Vec2 screen = screen_from_raster(s_.screen_window, resolution_, cs.p_film);
  Vec3 origin(screen, 0.f), dir(0.f, 0.f, 1.f);
  if (s_.lens_radius > 0.f) {
    // pbrt-v4's lens is centred on the camera's origin, not on the ray's screen point: every
    // ray of this film point passes (screen, focal_distance), from anywhere on the disc.
    const Vec2 lens = s_.lens_radius * sample_uniform_disk_concentric(cs.p_lens);
    origin = Vec3(lens, 0.f);
    dir = glm::normalize(Vec3(screen, s_.focal_distance) - origin);
  }
  const float time = s_.shutter.time(cs.time);
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, time, scratch);
  Ray r{world_from_camera.point(origin), glm::normalize(world_from_camera.vector(dir)), kInfinity, time};
  return CameraRay{r, SampledSpectrum(1.f), 1.f};
}

std::string OrthographicCamera::to_string() const {
  const Vec4& w = s_.screen_window;
  return fmt::format("orthographic camera: screen window [{}, {}] x [{}, {}], lens radius {}, focal distance {}", w[0],
                     w[1], w[2], w[3], s_.lens_radius, s_.focal_distance);
}

const PluginSpec& orthographic_camera_spec() {
  static const PluginSpec spec{
      "Camera",
      "a parallel projection of the screen window, with an optional thin lens",
      "—",
      {
          screen_window_param(),
          frame_aspect_ratio_param(),
          param::real("lensradius", 0)
              .at_least(0)
              .with_unit("scene units")
              .describe("thin-lens aperture radius (the disc is centred on the camera's origin, as pbrt-v4)"),
          param::real("focaldistance", 1e6)
              .above(0)
              .with_unit("scene units")
              .describe("distance of the plane in focus"),
          shutter_open_param(),
          shutter_close_param(),
      }};
  return spec;
}

std::unique_ptr<Camera> create_orthographic_camera(const CameraContext& ctx) {
  const PluginParams p(ctx.params, orthographic_camera_spec(), "orthographic");
  OrthographicCamera::Settings s;
  s.screen_window = read_screen_window(p, ctx.resolution);
  s.lens_radius = p.get_float("lensradius");
  s.focal_distance = p.get_float("focaldistance");
  // The shutter interval is also the film's exposure (scene_builder.cpp checks that it opens).
  s.shutter = read_shutter(p);
  return std::make_unique<OrthographicCamera>(ctx.world_from_camera, ctx.resolution, s, ctx.world_from_camera_motion);
}

}  // namespace eyetrace
