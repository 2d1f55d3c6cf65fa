#include "textures/noise_textures.h"

#include "textures/perlin_noise.h"
#include "textures/texture_mapping.h"

namespace eyetrace {

namespace {

enum class Kind { FBm, Wrinkled, Windy };

class NoiseTexture final : public FloatTexture {
 public:
  NoiseTexture(Kind kind, TextureMapping3D map, float omega, int octaves)
      : kind_(kind), map_(map), omega_(omega), octaves_(octaves) {}
  float evaluate(const TextureEvalContext& ctx) const override {
    const Vec3 p = map_.map(ctx);
    switch (kind_) {
      case Kind::FBm: return fbm(p, omega_, octaves_);
      case Kind::Wrinkled: return turbulence(p, omega_, octaves_);
      case Kind::Windy: return std::abs(fbm(0.1f * p, 0.5f, 3)) * fbm(p, 0.5f, 6);
    }
    return 0.f;
  }

 private:
  Kind kind_;
  TextureMapping3D map_;
  float omega_;
  int octaves_;
};

std::vector<ParamSpec> octave_params() {
  return {param::integer("octaves", 8).range(1, 64).describe("noise octaves summed"),
          param::real("roughness", 0.5).range(0, 1).describe("weight ratio of successive octaves")};
}

std::unique_ptr<FloatTexture> create(const TextureContext& ctx, const PluginSpec& spec, const char* name, Kind kind) {
  const PluginParams p(ctx.params, spec, name);
  const bool octaves = kind != Kind::Windy;
  return std::make_unique<NoiseTexture>(kind, TextureMapping3D::read(ctx), octaves ? p.get_float("roughness") : 0.5f,
                                        octaves ? p.get_int("octaves") : 0);
}

}  // namespace

const PluginSpec& fbm_texture_spec() {
  static const PluginSpec spec{"Texture", "fractional Brownian motion: a sum of Perlin noise octaves (float only)",
                               "Every octave is summed (pbrt-v4 drops those finer than a pixel)", octave_params()};
  return spec;
}

const PluginSpec& wrinkled_texture_spec() {
  static const PluginSpec spec{"Texture", "turbulence: a sum of |Perlin noise| octaves (float only)",
                               "Every octave is summed (pbrt-v4 replaces those finer than a pixel by 0.2)",
                               octave_params()};
  return spec;
}

const PluginSpec& windy_texture_spec() {
  static const PluginSpec spec{"Texture",
                               "wind-blown waves: |fbm(0.1 p)| x fbm(p) (float only)",
                               "Every octave is summed (pbrt-v4 drops those finer than a pixel)",
                               {}};
  return spec;
}

std::unique_ptr<FloatTexture> create_fbm_texture(const TextureContext& ctx) {
  return create(ctx, fbm_texture_spec(), "fbm", Kind::FBm);
}
std::unique_ptr<FloatTexture> create_wrinkled_texture(const TextureContext& ctx) {
  return create(ctx, wrinkled_texture_spec(), "wrinkled", Kind::Wrinkled);
}
std::unique_ptr<FloatTexture> create_windy_texture(const TextureContext& ctx) {
  return create(ctx, windy_texture_spec(), "windy", Kind::Windy);
}

}  // namespace eyetrace
