// pbrt-v4's "point" light: an isotropic point source of radiant intensity I (W/sr).
// Parameters: "I" (spectrum, default white), "scale" (1), "power" (total luminous power:
// rescales I so that 4 pi * luminance(I) equals it; "scale" still multiplies on top, as in
// pbrt-v4), "from" (position in light space, (0,0,0)).
#pragma once
#include <memory>

#include "core/light.h"
#include "lights/light_params.h"
#include "scene/registry.h"

namespace eyetrace {

class PointLight : public Light {
 public:
  PointLight(const Vec3& position, const Spectrum& intensity)
      : p_(position), I_(intensity), power_(4.f * kPi * channel_mean(intensity)) {}

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  // Uniformly over the sphere of directions (as pbrt-v4).
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  bool emits_photons() const override { return true; }
  bool is_delta() const override { return true; }
  float power() const override { return power_; }

  const Vec3& position() const { return p_; }
  const Spectrum& intensity() const { return I_; }

 private:
  Vec3 p_;
  Spectrum I_;
  float power_;  // scale folded in
};

const PluginSpec& point_light_spec();
std::unique_ptr<Light> create_point_light(const LightContext& ctx);

}  // namespace eyetrace
