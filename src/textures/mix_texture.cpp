#include "textures/mix_texture.h"

#include "scene/texture_store.h"

namespace eyetrace {

namespace {

template <typename Base, typename Value>
class MixTexture final : public Base {
 public:
  MixTexture(const Base* tex1, const Base* tex2, const FloatTexture* amount)
      : tex1_(tex1), tex2_(tex2), amount_(amount) {}
  Value evaluate(const TextureEvalContext& ctx) const override {
    float a = amount_->evaluate(ctx);
    // Skip the texture whose weight is zero (it may be expensive).
    Value t1 = a != 1.f ? tex1_->evaluate(ctx) : Value(0.f);
    Value t2 = a != 0.f ? tex2_->evaluate(ctx) : Value(0.f);
    return (1.f - a) * t1 + a * t2;
  }

 private:
  const Base* tex1_;
  const Base* tex2_;
  const FloatTexture* amount_;
};

}  // namespace

std::unique_ptr<FloatTexture> create_mix_float_texture(const TextureContext& ctx) {
  const FloatTexture* tex1 = ctx.textures.float_param(ctx.params, "tex1", 0.f);
  const FloatTexture* tex2 = ctx.textures.float_param(ctx.params, "tex2", 1.f);
  const FloatTexture* amount = ctx.textures.float_param(ctx.params, "amount", 0.5f);
  return std::make_unique<MixTexture<FloatTexture, float>>(tex1, tex2, amount);
}

std::unique_ptr<SpectrumTexture> create_mix_spectrum_texture(const TextureContext& ctx) {
  const SpectrumTexture* tex1 = ctx.textures.spectrum_param(ctx.params, "tex1", RGB(0.f));
  const SpectrumTexture* tex2 = ctx.textures.spectrum_param(ctx.params, "tex2", RGB(1.f));
  const FloatTexture* amount = ctx.textures.float_param(ctx.params, "amount", 0.5f);
  return std::make_unique<MixTexture<SpectrumTexture, RGB>>(tex1, tex2, amount);
}

}  // namespace eyetrace
