#include "textures/checkerboard_texture.h"

#include <cmath>

#include "scene/texture_store.h"
#include "textures/texture_mapping.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

// 0 on even cells [2k, 2k+1), 1 on odd ones; exact for every finite double.
double parity(double x) { return std::floor(x) - 2.0 * std::floor(x / 2.0); }

// The 1D square wave c(x) = +1 on even cells, -1 on odd ones, has a periodic second
// antiderivative P (period 2, up to a linear term that cancels below).
double square_wave_p(double x) {
  x -= 2.0 * std::floor(x / 2.0);
  return x <= 1.0 ? 0.5 * x * x - 0.5 * x : 1.5 * x - 0.5 * x * x - 1.0;
}

// c(x) filtered by a triangle of half-width r: (P(x+r) - 2 P(x) + P(x-r)) / r^2.
double filtered_square_wave(double x, double r) {
  if (std::floor(x - r) == std::floor(x + r)) return 1.0 - 2.0 * parity(x);
  double v = (square_wave_p(x + r) - 2.0 * square_wave_p(x) + square_wave_p(x - r)) / (r * r);
  return std::clamp(v, -1.0, 1.0);
}

template <typename Base>
class CheckerboardTexture final : public TextureOf<Base> {
  using Value = typename TextureOf<Base>::Value;

 public:
  CheckerboardTexture(const Base* tex1, const Base* tex2, int dimension, TextureMapping2D map2, TextureMapping3D map3)
      : tex1_(tex1), tex2_(tex2), dimension_(dimension), map2_(map2), map3_(map3) {}

  Value value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    float w;
    if (dimension_ == 2) {
      TextureCoords c = map2_.map(ctx);
      w = checkerboard_2d(c.st, c.width);
    } else {
      w = checkerboard_3d(map3_.map(ctx));
    }
    Value t1 = w != 1.f ? TextureOf<Base>::of(*tex1_, ctx, lambda) : Value(0.f);
    Value t2 = w != 0.f ? TextureOf<Base>::of(*tex2_, ctx, lambda) : Value(0.f);
    return (1.f - w) * t1 + w * t2;
  }

 private:
  const Base* tex1_;
  const Base* tex2_;
  int dimension_;
  TextureMapping2D map2_;
  TextureMapping3D map3_;
};

template <typename Base>
std::unique_ptr<Base> create(const TextureContext& ctx, const PluginParams& p, const Base* tex1, const Base* tex2) {
  int dimension = p.get_int("dimension");
  TextureMapping2D map2;
  TextureMapping3D map3;
  if (dimension == 2) {
    map2 = TextureMapping2D::read(ctx, p);
  } else {
    TextureMapping2D::reject(p, "a 3-D checkerboard has no 2-D mapping");
    map3 = TextureMapping3D::read(ctx);
  }
  return std::make_unique<CheckerboardTexture<Base>>(tex1, tex2, dimension, map2, map3);
}

}  // namespace

float checkerboard_2d(Vec2 st, float r) {
  // Half-width 1.5x the footprint, as pbrt-v4 widens its triangle filter.
  if (!std::isfinite(st.x) || !std::isfinite(st.y)) return 0.f;
  double h = std::isfinite(r) ? 1.5 * double(std::max(r, 0.f)) : 0.0;
  double v = filtered_square_wave(st.x, h) * filtered_square_wave(st.y, h);
  return float(0.5 - 0.5 * v);
}

float checkerboard_3d(const Vec3& p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0.f;
  double sum = parity(p.x) + parity(p.y) + parity(p.z);
  return parity(sum) != 0.0 ? 1.f : 0.f;
}

const PluginSpec& checkerboard_texture_spec() {
  static const PluginSpec spec{
      "Texture", "alternating tex1 and tex2 in (s, t) squares (filtered) or texture-space cubes", "—",
      std::vector<ParamSpec>{param::any_texture("tex1", 1).describe("of the texture's kind"),
                             param::any_texture("tex2", 0).describe("of the texture's kind"),
                             param::integer("dimension", 2).range(2, 3).describe("2: in (s, t); 3: in texture space")} +
          TextureMapping2D::declared()};
  return spec;
}

std::unique_ptr<FloatTexture> create_checkerboard_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, checkerboard_texture_spec(), "checkerboard");
  return create<FloatTexture>(ctx, p, ctx.textures.float_param(p, "tex1"), ctx.textures.float_param(p, "tex2"));
}

std::unique_ptr<SpectrumTexture> create_checkerboard_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, checkerboard_texture_spec(), "checkerboard");
  return create<SpectrumTexture>(ctx, p, ctx.textures.spectrum_param(p, "tex1"),
                                 ctx.textures.spectrum_param(p, "tex2"));
}

}  // namespace eyetrace
