#include "textures/mix_texture.h"

#include "scene/texture_store.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

template <typename Base>
class MixTexture final : public TextureOf<Base> {
  using Value = typename TextureOf<Base>::Value;

 public:
  MixTexture(const Base* tex1, const Base* tex2, const FloatTexture* amount)
      : tex1_(tex1), tex2_(tex2), amount_(amount) {}
  Value value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    float a = amount_->evaluate(ctx);
    // Skip the texture whose weight is zero (it may be expensive).
    Value t1 = a != 1.f ? TextureOf<Base>::of(*tex1_, ctx, lambda) : Value(0.f);
    Value t2 = a != 0.f ? TextureOf<Base>::of(*tex2_, ctx, lambda) : Value(0.f);
    return (1.f - a) * t1 + a * t2;
  }

 private:
  const Base* tex1_;
  const Base* tex2_;
  const FloatTexture* amount_;
};

}  // namespace

const PluginSpec& mix_texture_spec() {
  static const PluginSpec spec{
      "Texture",
      "(1 − amount) tex1 + amount tex2",
      "—",
      {param::any_texture("tex1", 0).describe("of the texture's kind"),
       param::any_texture("tex2", 1).describe("of the texture's kind"), param::float_texture("amount", 0.5)}};
  return spec;
}

std::unique_ptr<FloatTexture> create_mix_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, mix_texture_spec(), "mix");
  return std::make_unique<MixTexture<FloatTexture>>(
      ctx.textures.float_param(p, "tex1"), ctx.textures.float_param(p, "tex2"), ctx.textures.float_param(p, "amount"));
}

std::unique_ptr<SpectrumTexture> create_mix_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, mix_texture_spec(), "mix");
  return std::make_unique<MixTexture<SpectrumTexture>>(ctx.textures.spectrum_param(p, "tex1"),
                                                       ctx.textures.spectrum_param(p, "tex2"),
                                                       ctx.textures.float_param(p, "amount"));
}

}  // namespace eyetrace
