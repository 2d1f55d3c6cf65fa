#include "lights/point_light.h"

#include "lights/light_params.h"

namespace eyetrace {

std::optional<LightLiSample> PointLight::sample_li(const LightSampleContext& ctx, Vec2) const {
  Vec3 d = p_ - ctx.p;
  float dist2 = glm::dot(d, d);
  // A shading point on the light itself receives no defined irradiance.
  if (!(dist2 > 0.f) || !std::isfinite(dist2)) return std::nullopt;
  LightLiSample s;
  s.L = I_ / dist2;
  s.wi = d / std::sqrt(dist2);
  s.pdf = 1.f;
  s.p_light = p_;
  return s;
}

float PointLight::power() const { return 4.f * kPi * channel_mean(I_); }

std::unique_ptr<Light> create_point_light(const LightContext& ctx) {
  const ParameterList& params = ctx.params;
  RGB I = emission_param(params, "I");
  float scale = scale_param(params);
  std::optional<float> phi = positive_param(params, "power");
  Vec3 from = params.get_point3("from", Vec3(0.f));
  scale *= photometric_factor(phi, 4.f * kPi * luminance(I));
  return std::make_unique<PointLight>(ctx.world_from_light.point(from), I * scale);
}

}  // namespace eyetrace
