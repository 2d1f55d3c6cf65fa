#include "lights/projection_light.h"

#include "core/sampling.h"
#include "lights/light_image.h"
#include "lights/light_params.h"

namespace eyetrace {

// pbrt-v4's screen window for the image's aspect a: [-a, a] x [-1, 1] when wider than tall,
// else [-1, 1] x [-1/a, 1/a]; on the plane z = 1 it is that times tan(fov / 2).
Vec2 ProjectionLight::half_extent(int width, int height, float fov_deg) {
  const float aspect = float(width) / float(height), t = std::tan(radians(fov_deg) / 2.f);
  return aspect > 1.f ? Vec2(aspect * t, t) : Vec2(t, t / aspect);
}

ProjectionLight::ProjectionLight(const Transform& world_from_light, RGBImage image, float fov_deg, float scale)
    : world_from_light_(world_from_light),
      light_from_world_(world_from_light.inverse()),
      p_(world_from_light.point(Vec3(0.f))),
      image_(std::move(image)),
      half_(half_extent(image_.width, image_.height, fov_deg)),
      cos_max_(1.f / std::sqrt(1.f + half_.x * half_.x + half_.y * half_.y)),
      scale_(scale) {
  power_rgb_ = scale_ * integrate_over_pixels(image_.width, image_.height, fov_deg,
                                              [&](int x, int y) { return image_.at(x, y); });
}

RGB ProjectionLight::intensity_rgb(const Vec3& w) const {
  const Vec3 wl = light_from_world_.vector(w);
  const float len = glm::length(wl);
  // pbrt-v4's near plane: nothing at or behind z = 1e-3 of a unit direction.
  if (!(len > 0.f) || !std::isfinite(len) || !(wl.z / len >= 1e-3f)) return RGB(0.f);
  const Vec2 plane(wl.x / wl.z, wl.y / wl.z);
  if (std::abs(plane.x) > half_.x || std::abs(plane.y) > half_.y) return RGB(0.f);
  // Raster rows grow downwards: the top row (v = 0) looks towards the light's +y.
  const Vec2 uv(0.5f * (plane.x / half_.x + 1.f), 0.5f * (1.f - plane.y / half_.y));
  return scale_ * image_.nearest(uv);
}

std::optional<LightLiSample> ProjectionLight::sample_li(const LightSampleContext& ctx, Vec2,
                                                        const SampledWavelengths& lambda) const {
  const Vec3 d = p_ - ctx.p;
  const float dist2 = glm::dot(d, d);
  // A shading point on the light itself receives no defined irradiance.
  if (!(dist2 > 0.f) || !std::isfinite(dist2)) return std::nullopt;
  const Vec3 wi = d / std::sqrt(dist2);
  const RGB I = intensity_rgb(-wi);
  if (I == RGB(0.f)) return std::nullopt;
  LightLiSample s;
  s.L = rgb_emission(I, lambda) / dist2;
  s.wi = wi;
  s.pdf = 1.f;
  s.p_light = p_;
  return s;
}

std::optional<LightLeSample> ProjectionLight::sample_le(Vec2 u1, Vec2, const SampledWavelengths& lambda,
                                                        float time) const {
  const Vec3 w = world_from_light_.vector(sample_uniform_cone(u1, cos_max_));
  const float len = glm::length(w);
  if (!(len > 0.f) || !std::isfinite(len)) return std::nullopt;
  const RGB I = intensity_rgb(w);
  if (I == RGB(0.f)) return std::nullopt;
  LightLeSample s;
  s.L = rgb_emission(I, lambda);
  s.ray = Ray{p_, w / len, kInfinity, time};
  s.pdf_pos = 1.f;
  s.pdf_dir = uniform_cone_pdf(cos_max_);
  return s;
}

void ProjectionLight::pdf_le(const Vec3&, const Vec3&, const Vec3& w, float* pdf_pos, float* pdf_dir) const {
  *pdf_pos = 0.f;  // a point: no other position could have been sampled (pbrt-v4)
  const Vec3 wl = light_from_world_.vector(w);
  const float len = glm::length(wl);
  *pdf_dir = len > 0.f && wl.z / len >= cos_max_ ? uniform_cone_pdf(cos_max_) : 0.f;
}

// The light sampler's weight: pbrt-v4's Phi, averaged over the channels.
float ProjectionLight::power() const { return channel_mean(power_rgb_); }

const PluginSpec& projection_light_spec() {
  static const PluginSpec spec{
      "LightSource",
      "a point light projecting an image, like a slide projector",
      "An image with a non-finite value is an error, as in pbrt-v4. Its RGB is read in the scene's colour space "
      "(pbrt-v4: the image file's).",
      {scale_param_spec(), photometric_param_spec("power", "total power: the image's luminance over its solid angle"),
       param::real("fov", 90).open_range(0, 180).with_unit("deg").describe("across the image's shorter side"),
       param::string("filename").describe("the image projected (any format OpenImageIO reads)")}};
  return spec;
}

std::unique_ptr<Light> create_projection_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, projection_light_spec(), "projection");
  float scale = scale_param(params);
  const std::optional<float> phi = photometric_param(params, "power");
  const float fov = params.get_float("fov");
  RGBImage image = read_light_image(params, ctx.search_dir, "projection");
  const float emitted = ProjectionLight::integrate_over_pixels(image.width, image.height, fov,
                                                               [&](int x, int y) { return luminance(image.at(x, y)); });
  scale *= photometric_factor(phi, emitted);
  return std::make_unique<ProjectionLight>(ctx.world_from_light, std::move(image), fov, scale);
}

}  // namespace eyetrace
