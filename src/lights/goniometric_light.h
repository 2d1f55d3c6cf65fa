// pbrt-v4's "goniometric" light: a point source at the light's origin whose intensity towards
// each direction is "I" times a goniometric diagram, an image in pbrt-v4's equal-area octahedral
// mapping (lights/sphere_mapping.h; square), looked up at the nearest pixel. An RGB image is
// averaged to one channel per pixel, as pbrt-v4 does. As pbrt-v4 the image's sphere has its y
// and z exchanged: the image centre looks along the light's +y, its corners along -y, the middle
// of its bottom edge along +z. The light is placed and turned by the CTM (pbrt-v4 has no
// "from" or "to" for it).
// "power" makes 4 pi times the image's average equal it (I's own spectrum normalised to
// luminance 1, and, as in pbrt-v4, an RGB I's colour not counted); "scale" multiplies on top.
#pragma once
#include <memory>
#include <vector>

#include "core/light.h"
#include "core/transform.h"
#include "lights/rgb_image.h"
#include "scene/registry.h"

namespace eyetrace {

class GoniometricLight : public Light {
 public:
  // `diagram`: width x width values (row-major, top row first), finite and >= 0; `I`
  // includes "scale" and the "power" factor.
  GoniometricLight(const Transform& world_from_light, const Spectrum& I, std::vector<float> diagram, int width);

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  // Light paths leave uniformly over the sphere, as pbrt-v4's; a direction where the diagram is
  // zero gives no ray.
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  void pdf_le(const Vec3& p, const Vec3& n, const Vec3& w, float* pdf_pos, float* pdf_dir) const override;
  bool is_delta() const override { return true; }
  float power() const override;

  // The diagram's value towards world direction w (any length, pointing away from the light).
  float diagram_value(const Vec3& w) const;
  SampledSpectrum intensity(const Vec3& w, const SampledWavelengths& lambda) const {
    return diagram_value(w) * I_.sample(lambda);
  }
  const Vec3& position() const { return p_; }
  // The diagram's mean over the sphere (every pixel covers the same solid angle).
  float diagram_mean() const { return mean_; }

 private:
  Transform light_from_world_;
  Vec3 p_;
  Spectrum I_;
  std::vector<float> diagram_;
  int width_;
  float mean_;
};

// The per-pixel average of R, G and B (a grey image's one channel).
std::vector<float> channel_average(const RGBImage& image);

const PluginSpec& goniometric_light_spec();
std::unique_ptr<Light> create_goniometric_light(const LightContext& ctx);

}  // namespace eyetrace
