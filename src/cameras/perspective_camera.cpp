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
  const Vec3 lo = camera_direction(Vec2(0.f)), hi = camera_direction(Vec2(resolution));
  film_area_ = std::abs((hi.x - lo.x) * (hi.y - lo.y));
  lens_area_ = s_.lens_radius > 0.f ? kPi * sqr(s_.lens_radius) : 1.f;
}

bool PerspectiveCamera::on_film(const Ray& ray, float* cos_theta, Vec2* p_raster) const {
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, ray.time, scratch);
  const Transform camera_from_world = world_from_camera.inverse();
  const Vec3 o = camera_from_world.point(ray.o);
  const Vec3 d = glm::normalize(camera_from_world.vector(ray.d));
  *cos_theta = d.z;
  if (!(d.z > 0.f)) return false;
  // Every ray through a lens point and the film point's image on the plane of focus (the plane
  // z = 1 for a pinhole, whose rays all leave the origin): that image, seen from the pinhole,
  // is the film point (generate_ray's construction inverted).
  const float z = s_.lens_radius > 0.f ? s_.focal_distance : 1.f;
  const Vec3 focus = o + d * ((z - o.z) / d.z);
  const Vec2 screen(focus.x / (focus.z * tan_half_fov_), focus.y / (focus.z * tan_half_fov_));
  const Vec4& w = s_.screen_window;
  const Vec2 p((screen.x - w[0]) / (w[1] - w[0]) * float(resolution_.x),
               (w[3] - screen.y) / (w[3] - w[2]) * float(resolution_.y));
  *p_raster = p;
  return p.x >= 0.f && p.y >= 0.f && p.x <= float(resolution_.x) && p.y <= float(resolution_.y);
}

float PerspectiveCamera::we(const Ray& ray, Vec2* p_raster) const {
  float cos_theta = 0.f;
  Vec2 p(0.f);
  const bool in = on_film(ray, &cos_theta, &p);
  if (p_raster) *p_raster = p;
  if (!in) return 0.f;
  return 1.f / (film_area_ * lens_area_ * sqr(sqr(cos_theta)));
}

void PerspectiveCamera::pdf_we(const Ray& ray, float* pdf_pos, float* pdf_dir) const {
  float cos_theta = 0.f;
  Vec2 p(0.f);
  if (!on_film(ray, &cos_theta, &p)) {
    *pdf_pos = *pdf_dir = 0.f;
    return;
  }
  *pdf_pos = 1.f / lens_area_;
  *pdf_dir = 1.f / (film_area_ * cos_theta * cos_theta * cos_theta);
}

std::optional<CameraWiSample> PerspectiveCamera::sample_wi(const Vec3& p_ref, float time, Vec2 u) const {
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, time, scratch);
  const Vec2 lens = s_.lens_radius * sample_uniform_disk_concentric(u);
  CameraWiSample cs;
  cs.p_lens = world_from_camera.point(Vec3(lens, 0.f));
  cs.n_lens = glm::normalize(world_from_camera.vector(Vec3(0.f, 0.f, 1.f)));
  Vec3 wi = cs.p_lens - p_ref;
  const float dist2 = glm::dot(wi, wi);
  if (!(dist2 > 0.f)) return std::nullopt;
  wi /= std::sqrt(dist2);
  const float cos_lens = std::abs(glm::dot(cs.n_lens, wi));
  if (!(cos_lens > 0.f)) return std::nullopt;  // grazing the lens plane: no film point sees it
  cs.wi = wi;
  cs.pdf = dist2 / (cos_lens * lens_area_);
  cs.Wi = we(Ray{cs.p_lens, -wi, kInfinity, time}, &cs.p_raster);
  if (!(cs.Wi > 0.f) || !std::isfinite(cs.pdf)) return std::nullopt;
  return cs;
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
      "`perspective` as pbrt-v4, with its importance (We, PDF_We, SampleWi), so `bdpt` connects light paths to it "
      "(t = 1). `thinlens` is another name for it; `pinhole` is the same camera with "
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
