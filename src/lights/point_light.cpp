#include "lights/point_light.h"

#include "core/sampling.h"
#include "lights/light_params.h"

namespace eyetrace {

std::optional<LightLiSample> PointLight::sample_li(const LightSampleContext& ctx, Vec2,
                                                   const SampledWavelengths& lambda) const {
  Vec3 d = p_ - ctx.p;
  float dist2 = glm::dot(d, d);
  // A shading point on the light itself receives no defined irradiance.
  if (!(dist2 > 0.f) || !std::isfinite(dist2)) return std::nullopt;
  LightLiSample s;
  s.L = I_.sample(lambda) / dist2;
  s.wi = d / std::sqrt(dist2);
  s.pdf = 1.f;
  s.p_light = p_;
  return s;
}

std::optional<LightLeSample> PointLight::sample_le(Vec2 u1, Vec2, const SampledWavelengths& lambda, float time) const {
  LightLeSample s;
  s.L = I_.sample(lambda);
  s.ray = Ray{p_, sample_uniform_sphere(u1), kInfinity, time};
  s.pdf_pos = 1.f;
  s.pdf_dir = uniform_sphere_pdf();
  return s;
}

const PluginSpec& point_light_spec() {
  static const PluginSpec spec{"LightSource",
                               "light from a point, equal in every direction",
                               "—",
                               {emission_param_spec("I", "intensity"), scale_param_spec(),
                                photometric_param_spec("power", "total power (replaces I's luminance)"),
                                param::point3("from", Vec3(0.f)).describe("position")}};
  return spec;
}

std::unique_ptr<Light> create_point_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, point_light_spec(), "point");
  Spectrum I = emission_param(params, "I");
  float scale = scale_param(params);
  std::optional<float> phi = photometric_param(params, "power");
  Vec3 from = params.get_point3("from");
  scale *= photometric_factor(phi, 4.f * kPi * I.luminance());
  return std::make_unique<PointLight>(ctx.world_from_light.point(from), I.scaled(scale));
}

}  // namespace eyetrace
