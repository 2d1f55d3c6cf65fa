// pbrt-v4's "infinite" light: radiance arriving from every direction at infinity.
// Constant ("L", default white) or from an image ("filename"): a square image is pbrt-v4's
// equal-area octahedral map, a 2:1 image a latitude-longitude map (see sphere_mapping.h for
// both layouts: +z is the image centre, or the top row). The light's transform (the CTM at
// the LightSource; a rotation, as in pbrt-v4: a scaling CTM would skew the densities) turns
// map directions into the world, so pbrt scenes with +y up write "Rotate -90 1 0 0" first.
// Parameters: "scale" (1); "illuminance" rescales so that the luminous irradiance on a
// patch facing the map's +z is the value given (pi L for a constant map; for image maps
// pbrt-v4 weighs pixels by 2 pi / N instead of 4 pi / N and so renders them twice as bright
// as asked, eyetrace integrates the map as it is); "portal" (four world-space corners of a
// rectangle, lights/portal.h): the environment is seen only through it.
// Sampling: constant maps uniformly over the sphere (as pbrt-v4); image maps by luminance;
// with a portal, constant maps by area on the portal, image maps half and half.
#pragma once
#include <memory>

#include "core/light.h"
#include "core/transform.h"
#include "lights/environment_map.h"
#include "lights/light_params.h"
#include "lights/portal.h"
#include "scene/registry.h"

namespace eyetrace {

class UniformInfiniteLight : public Light {
 public:
  explicit UniformInfiniteLight(const Spectrum& L, std::optional<Portal> portal = std::nullopt)
      : L_(L), mean_(channel_mean(L)), portal_(std::move(portal)) {}

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction* hit) const override;
  SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const override;
  bool is_delta() const override { return false; }
  bool is_infinite() const override { return true; }
  // Light paths (pbrt-v4): a direction by sample_li's density and a uniform point of the disc
  // that bounds the scene, perpendicular to it (pdf_pos 1 / (pi r^2)). Not through a portal:
  // its density depends on the point it is seen from.
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  void pdf_le(const Vec3& p, const Vec3& n, const Vec3& w, float* pdf_pos, float* pdf_dir) const override;
  bool emits_rays() const override { return !portal_; }
  // Flux through the scene's bounding disc from the whole sphere: 4 pi^2 r^2 L; through a
  // portal, pi A L.
  float power() const override;
  void preprocess(const Bounds3& scene_bounds) override;

 private:
  Spectrum L_;
  float mean_;  // of L_ as RGB: the light sampler's weight
  std::optional<Portal> portal_;
  float scene_radius_ = 0.f;
  Vec3 scene_center_{0.f};
};

class ImageInfiniteLight : public Light {
 public:
  ImageInfiniteLight(EnvironmentMap map, const Transform& world_from_light, float scale,
                     std::optional<Portal> portal = std::nullopt);

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction* hit) const override;
  SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const override;
  bool is_delta() const override { return false; }
  bool is_infinite() const override { return true; }
  // As UniformInfiniteLight's, with directions by the map's luminance.
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  void pdf_le(const Vec3& p, const Vec3& n, const Vec3& w, float* pdf_pos, float* pdf_dir) const override;
  bool emits_rays() const override { return !portal_; }
  float power() const override;
  void preprocess(const Bounds3& scene_bounds) override;

  const EnvironmentMap& map() const { return map_; }

 private:
  Vec3 to_light(const Vec3& w) const;
  // The map's own luminance density of the world direction wi, mixed with the portal's.
  float density(const Vec3& p, const Vec3& wi) const;

  EnvironmentMap map_;
  Transform world_from_light_, light_from_world_;
  float scale_;
  std::optional<Portal> portal_;
  float scene_radius_ = 0.f;
  Vec3 scene_center_{0.f};
};

const PluginSpec& infinite_light_spec();
std::unique_ptr<Light> create_infinite_light(const LightContext& ctx);

}  // namespace eyetrace
