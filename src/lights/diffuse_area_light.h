// pbrt-v4's "diffuse" area light (AreaLightSource): a shape emitting radiance L uniformly
// in angle from the side its normal points to (both sides if "twosided").
// Parameters: "L" (default white), "scale" (1), "twosided" (false), "power" (rescales so
// that the luminous power pi A luminance(L) (x2 if two-sided) equals it; "scale" still
// multiplies, as in pbrt-v4), "filename" (an RGB image giving L over the shape's (u, v),
// looked up bilinearly at (u, 1 - v) as pbrt-v4 does; exclusive with "L").
//
// The emitting side is that of ShapeSample::n / SurfaceInteraction::n, which the shape has
// already flipped for ReverseOrientation (core/shape.h), so the context's
// reverse_orientation flag is not applied a second time here.
//
// On a shape with alpha cut-outs the cut-away points emit nothing (Shape::alpha_masked, as
// pbrt-v4). A shape of constant alpha 0 is an invisible emitter: no ray meets it, it emits
// everywhere, and it is treated as a delta light so that light sampling, the only strategy
// that reaches it, gets the whole MIS weight (pbrt-v4 makes it a DeltaPosition light).
//
// Sampling: uniform by area through Shape::sample_area, turned into a solid-angle density
// pdf_area * dist^2 / |cos(theta_light)|. pdf_li() uses 1 / area(), which is the density
// sample_area has when it is uniform over the shape (as every eyetrace shape's is).
#pragma once
#include <memory>
#include <optional>

#include "core/light.h"
#include "core/shape.h"
#include "lights/rgb_image.h"
#include "scene/registry.h"

namespace eyetrace {

class DiffuseAreaLight : public Light {
 public:
  // `scale` multiplies L or the image.
  DiffuseAreaLight(const Shape& shape, const Spectrum& L, float scale, bool two_sided,
                   std::optional<RGBImage> image = std::nullopt);

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction* hit) const override;
  SampledSpectrum L(const SurfaceInteraction& hit, const Vec3& w, const SampledWavelengths& lambda) const override;
  // The origin uniform by area, the direction cosine-distributed about the emitting side's
  // normal (either side, half and half, when two-sided), as pbrt-v4.
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  bool emits_photons() const override { return true; }
  bool is_delta() const override { return invisible_; }
  float power() const override;

  bool two_sided() const { return two_sided_; }

 private:
  // Radiance leaving a point with normal n and texture coordinates uv in direction w.
  SampledSpectrum emitted(const Vec3& n, Vec2 uv, const Vec3& w, const SampledWavelengths& lambda) const;

  const Shape& shape_;
  Spectrum L_;
  float scale_;
  bool two_sided_;
  std::optional<RGBImage> image_;
  float area_;
  float mean_;
  bool invisible_;  // mean of the emission (or image) as RGB, before scale: the light sampler's weight
};

const PluginSpec& diffuse_area_light_spec();
std::unique_ptr<Light> create_diffuse_area_light(const AreaLightContext& ctx);

}  // namespace eyetrace
