// pbrt-v4's "spot" light: a point source at "from" shining towards "to", full intensity I
// within (coneangle - conedeltaangle) of the axis, falling off by a smoothstep in
// cos(theta) to zero at "coneangle" (degrees; defaults 30 and 5).
// Parameters: "I" (default white), "scale" (1), "power" (rescales I so that the total
// luminous power 2 pi luminance(I) (1 - (cos_start + cos_end) / 2) equals it), "from"
// (0,0,0), "to" (0,0,1), all in light space. A conedeltaangle larger than coneangle (which
// pbrt-v4 turns into a falloff band mirrored about the axis) is a warning, and the falloff
// then spans the whole cone.
#pragma once
#include <memory>

#include "core/light.h"
#include "core/transform.h"
#include "scene/registry.h"

namespace eyetrace {

class SpotLight : public Light {
 public:
  // `light_from_world` measures angles in the light's own frame (as pbrt-v4 does, so a
  // non-uniform scale in the CTM distorts the cone like it distorts the scene).
  SpotLight(const Transform& world_from_light, const Vec3& from, const Vec3& to, const Spectrum& I,
            float cone_angle_deg, float falloff_start_deg);

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  // Uniformly within the cone of "coneangle" about the axis (as pbrt-v4; the cone is taken in
  // world space, exact unless the light's transform scales unevenly).
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  bool emits_photons() const override { return true; }
  bool is_delta() const override { return true; }
  float power() const override;

  // Radiant intensity towards world direction w (unit, pointing away from the light).
  SampledSpectrum intensity(const Vec3& w, const SampledWavelengths& lambda) const;
  const Vec3& position() const { return p_; }

 private:
  Transform light_from_world_;
  Vec3 p_;           // world position
  Vec3 axis_light_;  // unit axis in light space
  Vec3 axis_world_;  // unit axis in world space
  Spectrum I_;
  float mean_;  // of I_ as RGB: the light sampler's weight
  float cos_falloff_start_, cos_falloff_end_;
};

const PluginSpec& spot_light_spec();
std::unique_ptr<Light> create_spot_light(const LightContext& ctx);

}  // namespace eyetrace
