#include "textures/marble_texture.h"

#include <cmath>

#include "core/lerp.h"
#include "core/spectrum.h"
#include "textures/perlin_noise.h"
#include "textures/texture_mapping.h"

namespace eyetrace {

namespace {

// pbrt-v4's control points (MarbleTexture::Evaluate), sRGB.
constexpr float kColours[9][3] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f},
                                  {.5f, .5f, .5f},   {.6f, .59f, .58f}, {.58f, .58f, .6f},
                                  {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};

class MarbleTexture final : public SpectrumTexture {
 public:
  MarbleTexture(TextureMapping3D map, int octaves, float omega, float scale, float variation)
      : map_(map), octaves_(octaves), omega_(omega), scale_(scale), variation_(variation) {}
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    const Vec3 p = scale_ * map_.map(ctx);
    const float t = 0.5f + 0.5f * std::sin(p.y + variation_ * fbm(p, omega_, octaves_));
    // A reflectance whatever the material reads it as (pbrt-v4: RGBAlbedoSpectrum).
    return Spectrum::from_rgb(marble_colour(t), SpectrumType::Albedo).sample(lambda);
  }

 private:
  TextureMapping3D map_;
  int octaves_;
  float omega_, scale_, variation_;
};

}  // namespace

RGB marble_colour(float t) {
  if (!std::isfinite(t)) t = 0.f;
  t = std::clamp(t, 0.f, 1.f);
  // Six overlapping cubic segments over the nine points (pbrt-v4's nSeg = 9 - 3).
  constexpr int kSegments = 6;
  const int first = std::min(int(std::floor(t * kSegments)), kSegments - 1);
  const float s = t * kSegments - float(first);
  RGB c[4];
  for (int i = 0; i < 4; ++i) c[i] = RGB(kColours[first + i][0], kColours[first + i][1], kColours[first + i][2]);
  // de Casteljau's algorithm for the cubic Bezier curve with control points c0..c3.
  const RGB a = lerp(s, c[0], c[1]), b = lerp(s, c[1], c[2]), d = lerp(s, c[2], c[3]);
  return 1.5f * lerp(s, lerp(s, a, b), lerp(s, b, d));
}

const PluginSpec& marble_texture_spec() {
  static const PluginSpec spec{"Texture",
                               "marble veins: a sine perturbed by fbm, through pbrt-v4's colour spline",
                               "Every fbm octave is summed (pbrt-v4 drops those finer than a pixel)",
                               {param::integer("octaves", 8).range(1, 64).describe("fbm octaves"),
                                param::real("roughness", 0.5).range(0, 1).describe("fbm weight ratio"),
                                param::real("scale", 1).describe("multiplies the texture-space point"),
                                param::real("variation", 0.2).describe("fbm's share of the sine's argument")}};
  return spec;
}

std::unique_ptr<SpectrumTexture> create_marble_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, marble_texture_spec(), "marble");
  return std::make_unique<MarbleTexture>(TextureMapping3D::read(ctx), p.get_int("octaves"), p.get_float("roughness"),
                                         p.get_float("scale"), p.get_float("variation"));
}

}  // namespace eyetrace
