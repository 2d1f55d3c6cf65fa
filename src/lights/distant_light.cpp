#include "lights/distant_light.h"

#include "core/sampling.h"
#include "lights/light_params.h"

namespace eyetrace {

std::optional<LightLiSample> DistantLight::sample_li(const LightSampleContext& ctx, Vec2,
                                                     const SampledWavelengths& lambda) const {
  LightLiSample s;
  s.L = L_.sample(lambda);
  s.wi = w_;
  s.pdf = 1.f;
  // Two radii from any point inside the bounds is outside them: the shadow ray sees all.
  float r = scene_radius_ > 0.f ? scene_radius_ : 1.f;
  s.p_light = ctx.p + w_ * (2.f * r);
  s.n_light = -w_;
  return s;
}

std::optional<LightLeSample> DistantLight::sample_le(Vec2 u1, Vec2, const SampledWavelengths& lambda,
                                                     float time) const {
  if (!(scene_radius_ > 0.f)) return std::nullopt;
  const Frame frame(w_);
  const Vec2 d = sample_uniform_disk_concentric(u1);
  const Vec3 p_disk = scene_center_ + scene_radius_ * (d.x * frame.s + d.y * frame.t);
  LightLeSample s;
  s.L = L_.sample(lambda);
  s.ray = Ray{p_disk + scene_radius_ * w_, -w_, kInfinity, time};
  s.pdf_pos = 1.f / (kPi * scene_radius_ * scene_radius_);
  s.pdf_dir = 1.f;
  return s;
}

float DistantLight::power() const { return kPi * scene_radius_ * scene_radius_ * mean_; }

void DistantLight::preprocess(const Bounds3& scene_bounds) {
  float r = scene_bounds.radius();
  scene_radius_ = std::isfinite(r) ? r : 0.f;
  scene_center_ = scene_radius_ > 0.f ? scene_bounds.center() : Vec3(0.f);
}

const PluginSpec& distant_light_spec() {
  static const PluginSpec spec{
      "LightSource",
      "parallel light from one direction (the sun)",
      "—",
      {emission_param_spec("L", "radiance"), scale_param_spec(),
       photometric_param_spec("illuminance", "at a surface facing the light (replaces L's luminance)"),
       param::point3("from", Vec3(0.f)).describe("the light travels from `from` to `to`"),
       param::point3("to", Vec3(0.f, 0.f, 1.f))}};
  return spec;
}

std::unique_ptr<Light> create_distant_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, distant_light_spec(), "distant");
  Spectrum L = emission_param(params, "L");
  float scale = scale_param(params);
  std::optional<float> E = photometric_param(params, "illuminance");
  Vec3 from = params.get_point3("from");
  Vec3 to = params.get_point3("to");
  Vec3 w = ctx.world_from_light.vector(from - to);
  float len = glm::length(w);
  if (!(len > 0.f) || !std::isfinite(len))
    params.fail(params.has("to") ? "to" : "from", "\"from\" and \"to\" coincide: the light has no direction");
  scale *= photometric_factor(E, L.luminance());
  return std::make_unique<DistantLight>(w / len, L.scaled(scale));
}

}  // namespace eyetrace
