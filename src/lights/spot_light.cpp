#include "lights/spot_light.h"

#include "core/sampling.h"
#include "lights/light_params.h"

namespace eyetrace {
namespace {

float smooth_step(float x, float a, float b) {
  if (a == b) return x < a ? 0.f : 1.f;
  float t = std::clamp((x - a) / (b - a), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

}  // namespace

SpotLight::SpotLight(const Transform& world_from_light, const Vec3& from, const Vec3& to, const Spectrum& I,
                     float cone_angle_deg, float falloff_start_deg)
    : light_from_world_(world_from_light.inverse()),
      p_(world_from_light.point(from)),
      axis_light_(glm::normalize(to - from)),
      axis_world_(glm::normalize(world_from_light.vector(to - from))),
      I_(I),
      mean_(channel_mean(I)),
      cos_falloff_start_(std::cos(radians(falloff_start_deg))),
      cos_falloff_end_(std::cos(radians(cone_angle_deg))) {}

SampledSpectrum SpotLight::intensity(const Vec3& w, const SampledWavelengths& lambda) const {
  Vec3 wl = light_from_world_.vector(w);
  float len = glm::length(wl);
  if (!(len > 0.f)) return SampledSpectrum(0.f);
  float cos_theta = glm::dot(wl / len, axis_light_);
  return smooth_step(cos_theta, cos_falloff_end_, cos_falloff_start_) * I_.sample(lambda);
}

std::optional<LightLiSample> SpotLight::sample_li(const LightSampleContext& ctx, Vec2,
                                                  const SampledWavelengths& lambda) const {
  Vec3 d = p_ - ctx.p;
  float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.f) || !std::isfinite(dist2)) return std::nullopt;
  Vec3 wi = d / std::sqrt(dist2);
  SampledSpectrum I = intensity(-wi, lambda);
  if (is_black(I)) return std::nullopt;
  LightLiSample s;
  s.L = I / dist2;
  s.wi = wi;
  s.pdf = 1.f;
  s.p_light = p_;
  return s;
}

std::optional<LightLeSample> SpotLight::sample_le(Vec2 u1, Vec2, const SampledWavelengths& lambda, float time) const {
  const Vec3 w = Frame(axis_world_).to_world(sample_uniform_cone(u1, cos_falloff_end_));
  LightLeSample s;
  s.L = intensity(w, lambda);
  if (is_black(s.L)) return std::nullopt;
  s.ray = Ray{p_, w, kInfinity, time};
  s.pdf_pos = 1.f;
  s.pdf_dir = uniform_cone_pdf(cos_falloff_end_);
  return s;
}

// The smoothstep is symmetric about the middle of [cos_end, cos_start], so the falloff
// band contributes exactly half its solid angle.
float SpotLight::power() const { return mean_ * 2.f * kPi * (1.f - 0.5f * (cos_falloff_start_ + cos_falloff_end_)); }

const PluginSpec& spot_light_spec() {
  static const PluginSpec spec{
      "LightSource",
      "a point light limited to a cone, with a smooth falloff at its edge",
      "`conedeltaangle` larger than `coneangle` warns and makes the falloff start at the axis.",
      {emission_param_spec("I", "intensity on the axis"), scale_param_spec(),
       photometric_param_spec("power", "total power (replaces I's luminance)"),
       param::point3("from", Vec3(0.f)).describe("position"),
       param::point3("to", Vec3(0.f, 0.f, 1.f)).describe("a point on the axis"),
       param::real("coneangle", 30).range(0, 180).with_unit("deg").describe("half-angle of the cone"),
       param::real("conedeltaangle", 5).range(0, 180).with_unit("deg").describe("width of the falloff")}};
  return spec;
}

std::unique_ptr<Light> create_spot_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, spot_light_spec(), "spot");
  Spectrum I = emission_param(params, "I");
  float scale = scale_param(params);
  std::optional<float> phi = photometric_param(params, "power");
  Vec3 from = params.get_point3("from");
  Vec3 to = params.get_point3("to");
  float cone = params.get_float("coneangle");
  float delta = params.get_float("conedeltaangle");
  if (from == to)
    params.fail(params.has("to") ? "to" : "from", "\"from\" and \"to\" coincide: the spot has no direction");
  if (delta > cone) {
    // pbrt-v4 would take cos of a negative start angle; a falloff across the whole cone is
    // what such a scene means.
    params.warn_param("conedeltaangle",
                      fmt::format("{} exceeds \"coneangle\" {}; the falloff starts at the axis", delta, cone));
    delta = cone;
  }
  float cos_start = std::cos(radians(cone - delta)), cos_end = std::cos(radians(cone));
  float k_e = 2.f * kPi * (1.f - 0.5f * (cos_start + cos_end));
  scale *= photometric_factor(phi, k_e * I.luminance());
  return std::make_unique<SpotLight>(ctx.world_from_light, from, to, I.scaled(scale), cone, cone - delta);
}

}  // namespace eyetrace
