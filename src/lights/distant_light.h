// pbrt-v4's "distant" light: radiance L arriving from one direction (a sun at infinity).
// Light travels from "from" (0,0,0) towards "to" (0,0,1), both in light space.
// Parameters: "L" (default white), "scale" (1), "illuminance" (rescales L so that the
// luminous irradiance on a patch facing the light, luminance(L), equals it; "scale" still
// multiplies, as in pbrt-v4 since its issue #130 fix).
#pragma once
#include <memory>

#include "core/light.h"
#include "lights/light_params.h"
#include "scene/registry.h"

namespace eyetrace {

class DistantLight : public Light {
 public:
  // `to_light`: unit world direction from the scene towards the light.
  DistantLight(const Vec3& to_light, const Spectrum& L) : w_(to_light), L_(L), mean_(channel_mean(L)) {}

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  // Parallel rays through a disc of the scene's bounding radius, facing the light, outside the
  // scene (as pbrt-v4).
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  bool emits_photons() const override { return true; }
  bool is_delta() const override { return true; }
  // The flux through the scene's bounding disc: pi r^2 L (0 before preprocess()).
  float power() const override;
  void preprocess(const Bounds3& scene_bounds) override;

  const Vec3& direction_to_light() const { return w_; }

 private:
  Vec3 w_;
  Spectrum L_;
  float mean_;  // of L_ as RGB: the light sampler's weight
  float scene_radius_ = 0.f;
  Vec3 scene_center_{0.f};
};

const PluginSpec& distant_light_spec();
std::unique_ptr<Light> create_distant_light(const LightContext& ctx);

}  // namespace eyetrace
