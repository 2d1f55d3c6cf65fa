#include "lights/infinite_light.h"

#include <filesystem>

#include "core/sampling.h"
#include "lights/light_params.h"
#include "scene/scene_files.h"

namespace eyetrace {
namespace {

float usable_radius(float r) { return r > 0.f && std::isfinite(r) ? r : 1.f; }

LightLiSample make_sample(const LightSampleContext& ctx, const SampledSpectrum& L, const Vec3& wi, float pdf,
                          float radius) {
  LightLiSample s;
  s.L = L;
  s.wi = wi;
  s.pdf = pdf;
  // Two scene radii from a point inside the scene is outside it.
  s.p_light = ctx.p + wi * (2.f * usable_radius(radius));
  s.n_light = -wi;
  return s;
}

float scene_radius_of(const Bounds3& b) {
  float r = b.radius();
  return std::isfinite(r) ? r : 0.f;
}

}  // namespace

std::optional<LightLiSample> UniformInfiniteLight::sample_li(const LightSampleContext& ctx, Vec2 u,
                                                             const SampledWavelengths& lambda) const {
  if (mean_ == 0.f) return std::nullopt;
  if (!portal_)
    return make_sample(ctx, L_.sample(lambda), sample_uniform_sphere(u), uniform_sphere_pdf(), scene_radius_);
  const auto s = portal_->sample(ctx.p, u);
  if (!s) return std::nullopt;
  // The density from the direction itself, as pdf_li computes it (MIS weights must agree).
  const float pdf = portal_->pdf(ctx.p, s->first);
  if (!(pdf > 0.f)) return std::nullopt;
  return make_sample(ctx, L_.sample(lambda), s->first, pdf, scene_radius_);
}

float UniformInfiniteLight::pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction*) const {
  if (mean_ == 0.f) return 0.f;
  return portal_ ? portal_->pdf(ctx.p, wi) : uniform_sphere_pdf();  // wi: unit, as a ray direction
}

SampledSpectrum UniformInfiniteLight::Le(const Ray& ray, const SampledWavelengths& lambda) const {
  if (portal_ && !portal_->passes(ray.o, ray.d)) return SampledSpectrum(0.f);
  return L_.sample(lambda);
}

float UniformInfiniteLight::power() const {
  return portal_ ? kPi * portal_->area() * mean_ : 4.f * kPi * kPi * sqr(scene_radius_) * mean_;
}

void UniformInfiniteLight::preprocess(const Bounds3& scene_bounds) {
  scene_radius_ = scene_radius_of(scene_bounds);
  scene_center_ = scene_radius_ > 0.f ? scene_bounds.center() : Vec3(0.f);
}

std::optional<LightLeSample> UniformInfiniteLight::sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda,
                                                             float time) const {
  if (portal_ || !(scene_radius_ > 0.f)) return std::nullopt;
  const Vec3 to_light = sample_uniform_sphere(u1);
  const Frame frame(-to_light);
  const Vec2 d = sample_uniform_disk_concentric(u2);
  const Vec3 p_disk = scene_center_ + scene_radius_ * (d.x * frame.s + d.y * frame.t);
  LightLeSample s;
  s.L = L_.sample(lambda);
  s.ray = Ray{p_disk + scene_radius_ * to_light, -to_light, kInfinity, time};
  s.pdf_pos = 1.f / (kPi * scene_radius_ * scene_radius_);
  s.pdf_dir = uniform_sphere_pdf();
  return s;
}

ImageInfiniteLight::ImageInfiniteLight(EnvironmentMap map, const Transform& world_from_light, float scale,
                                       std::optional<Portal> portal)
    : map_(std::move(map)),
      world_from_light_(world_from_light),
      light_from_world_(world_from_light.inverse()),
      scale_(scale),
      portal_(std::move(portal)) {}

Vec3 ImageInfiniteLight::to_light(const Vec3& w) const {
  Vec3 wl = light_from_world_.vector(w);
  float len = glm::length(wl);
  return len > 0.f ? wl / len : Vec3(0.f, 0.f, 1.f);
}

std::optional<LightLiSample> ImageInfiniteLight::sample_li(const LightSampleContext& ctx, Vec2 u,
                                                           const SampledWavelengths& lambda) const {
  // With a portal, the first half of u.x picks the map's own sampling, the second the portal's.
  const bool by_portal = portal_ && u.x >= 0.5f;
  if (portal_) u.x = by_portal ? 2.f * u.x - 1.f : 2.f * u.x;
  Vec3 wi(0.f);
  if (by_portal) {
    const auto s = portal_->sample(ctx.p, u);
    if (!s) return std::nullopt;
    wi = s->first;
  } else {
    float map_pdf = 0.f;  // equals the density below unless wi rounds into another pixel
    std::optional<Vec3> wl = map_.sample(u, &map_pdf);
    if (!wl) return std::nullopt;
    wi = world_from_light_.vector(*wl);
    float len = glm::length(wi);
    if (!(len > 0.f)) return std::nullopt;
    wi /= len;
  }
  // Density and radiance from wi itself, so that pdf_li(wi) and Le along wi agree with this
  // sample to the last bit (MIS weights depend on it).
  const float pdf = density(ctx.p, wi);
  if (!(pdf > 0.f)) return std::nullopt;  // also: a map sample that misses the portal
  SampledSpectrum L = scale_ * rgb_emission(map_.radiance(to_light(wi)), lambda);
  if (is_black(L)) return std::nullopt;
  return make_sample(ctx, L, wi, pdf, scene_radius_);
}

float ImageInfiniteLight::density(const Vec3& p, const Vec3& wi) const {
  if (!portal_) return map_.pdf(to_light(wi));
  const float portal_pdf = portal_->pdf(p, wi);  // 0 exactly where wi misses the portal
  return portal_pdf > 0.f ? 0.5f * (map_.pdf(to_light(wi)) + portal_pdf) : 0.f;
}

float ImageInfiniteLight::pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction*) const {
  return density(ctx.p, wi);  // wi: unit, as a ray direction
}

SampledSpectrum ImageInfiniteLight::Le(const Ray& ray, const SampledWavelengths& lambda) const {
  if (portal_ && !portal_->passes(ray.o, ray.d)) return SampledSpectrum(0.f);
  return scale_ * rgb_emission(map_.radiance(to_light(ray.d)), lambda);
}

float ImageInfiniteLight::power() const {
  const float area = portal_ ? kPi * portal_->area() : 4.f * kPi * kPi * sqr(scene_radius_);
  return area * scale_ * channel_mean(map_.mean_radiance());
}

void ImageInfiniteLight::preprocess(const Bounds3& scene_bounds) { scene_radius_ = scene_radius_of(scene_bounds); }

namespace {

EnvironmentMap read_environment_map(const PluginParams& params, const std::string& path) {
  if (!std::filesystem::exists(path))
    params.fail_missing_file("filename", fmt::format("environment image \"{}\" not found", path));
  std::string error;
  size_t non_finite = 0;
  std::optional<RGBImage> image = read_rgb_image(path, &error, &non_finite);
  if (!image) params.fail("filename", fmt::format("cannot read environment image \"{}\": {}", path, error));
  if (non_finite > 0)
    params.warn_param("filename", fmt::format("\"{}\" has {} non-finite value(s), read as 0", path, non_finite));
  SphereMapping mapping;
  if (image->width == image->height) {
    mapping = SphereMapping::EqualArea;
  } else if (image->width == 2 * image->height) {
    mapping = SphereMapping::LatLong;
  } else {
    params.fail("filename", fmt::format("environment image \"{}\" is {}x{}: it must be square (pbrt-v4's "
                                        "equal-area map) or 2:1 (latitude-longitude)",
                                        path, image->width, image->height));
  }
  return EnvironmentMap(std::move(*image), mapping);
}

}  // namespace

const PluginSpec& infinite_light_spec() {
  static const PluginSpec spec{
      "LightSource",
      "light from every direction at infinity: uniform, or an environment image",
      "Latitude-longitude images are accepted. With a portal, the environment is looked up in its own map (pbrt-v4 "
      "resamples it into the portal's parameterisation, nearest pixel) and sampled half by the map's luminance, "
      "half uniformly over the portal's area (pbrt-v4: by luminance in the portal's parameterisation); a portal that "
      "is not a rectangle is an error (pbrt-v4 reports it and goes on).",
      {emission_param_spec("L", "radiance (default 1 when there is no file)"), scale_param_spec(),
       photometric_param_spec("illuminance", "the illuminance it gives an upward-facing surface"),
       param::string("filename")
           .describe("environment image, square (pbrt-v4's equal-area octahedral map) or 2:1 (latitude-longitude); not "
                     "with `L`"),
       param::point3s("portal").describe(
           "four world-space corners of a rectangle (a window) through which alone the environment is seen; its "
           "normal, (corner 3 - corner 0) x (corner 1 - corner 0), points out of the scene")}};
  return spec;
}

std::unique_ptr<Light> create_infinite_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, infinite_light_spec(), "infinite");
  std::optional<Spectrum> L = emission_param_or_null(params, "L");
  float scale = scale_param(params);
  std::optional<float> E = photometric_param(params, "illuminance");
  const std::string filename = params.has("filename") ? params.get_string("filename") : "";
  std::optional<Portal> portal;
  if (params.has("portal")) {
    std::string error;
    portal = Portal::make(params.get_point3s("portal"), &error);
    if (!portal) params.fail("portal", error);
  }

  if (filename.empty()) {
    const Spectrum Lc = L ? *L : emission_param(params, "L");  // absent: the declared default
    scale *= photometric_factor(E, kPi * Lc.luminance());
    return std::make_unique<UniformInfiniteLight>(Lc.scaled(scale), std::move(portal));
  }
  if (L) params.fail("filename", "an infinite light takes \"L\" or \"filename\", not both");
  EnvironmentMap map = read_environment_map(params, resolve_scene_file(ctx.search_dir, filename));
  scale *= photometric_factor(E, map.up_illuminance());
  return std::make_unique<ImageInfiniteLight>(std::move(map), ctx.world_from_light, scale, std::move(portal));
}

}  // namespace eyetrace
