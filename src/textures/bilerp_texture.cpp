#include "textures/bilerp_texture.h"

#include <array>

#include "textures/texture_mapping.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

constexpr std::array<const char*, 4> kCorners = {"v00", "v10", "v01", "v11"};

// The four corner weights at (s, t), in kCorners' order.
std::array<float, 4> corner_weights(Vec2 st) {
  const float s = st.x, t = st.y;
  return {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
}

class FloatBilerpTexture final : public FloatTexture {
 public:
  FloatBilerpTexture(TextureMapping2D map, std::array<float, 4> v) : map_(map), v_(v) {}
  float evaluate(const TextureEvalContext& ctx) const override {
    const std::array<float, 4> w = corner_weights(map_.map(ctx).st);
    return w[0] * v_[0] + w[1] * v_[1] + w[2] * v_[2] + w[3] * v_[3];
  }

 private:
  TextureMapping2D map_;
  std::array<float, 4> v_;
};

class SpectrumBilerpTexture final : public SpectrumTexture {
 public:
  SpectrumBilerpTexture(TextureMapping2D map, std::array<std::unique_ptr<SpectrumTexture>, 4> v)
      : map_(map), v_(std::move(v)) {}
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    const std::array<float, 4> w = corner_weights(map_.map(ctx).st);
    SampledSpectrum sum(0.f);
    for (int i = 0; i < 4; ++i)
      if (w[i] != 0.f) sum += w[i] * v_[i]->evaluate(ctx, lambda);
    return sum;
  }

 private:
  TextureMapping2D map_;
  std::array<std::unique_ptr<SpectrumTexture>, 4> v_;  // constants, read once (RGB in both readings)
};

}  // namespace

const PluginSpec& bilerp_texture_spec() {
  static const PluginSpec spec{"Texture", "bilinear interpolation of four corner values over (s, t)", "—",
                               std::vector<ParamSpec>{param::float_or_spectrum("v00", 0).describe("at (s, t) = (0, 0)"),
                                                      param::float_or_spectrum("v10", 0).describe("at (1, 0)"),
                                                      param::float_or_spectrum("v01", 1).describe("at (0, 1)"),
                                                      param::float_or_spectrum("v11", 1).describe("at (1, 1)")} +
                                   TextureMapping2D::declared()};
  return spec;
}

std::unique_ptr<FloatTexture> create_bilerp_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, bilerp_texture_spec(), "bilerp");
  std::array<float, 4> v{};
  for (int i = 0; i < 4; ++i) v[size_t(i)] = p.get_float(kCorners[size_t(i)]);
  return std::make_unique<FloatBilerpTexture>(TextureMapping2D::read(ctx, p), v);
}

std::unique_ptr<SpectrumTexture> create_bilerp_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, bilerp_texture_spec(), "bilerp");
  std::array<std::unique_ptr<SpectrumTexture>, 4> v;
  for (size_t i = 0; i < 4; ++i) {
    const SpectrumValue s = p.get_spectrum(kCorners[i], SpectrumType::Albedo);
    v[i] = s.rgb ? std::make_unique<ConstantSpectrumTexture>(*s.rgb)
                 : std::make_unique<ConstantSpectrumTexture>(s.spectrum);
  }
  return std::make_unique<SpectrumBilerpTexture>(TextureMapping2D::read(ctx, p), std::move(v));
}

}  // namespace eyetrace
