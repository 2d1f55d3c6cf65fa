#include "textures/scale_texture.h"

#include "scene/texture_store.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

template <typename Base>
class ScaleTexture final : public TextureOf<Base> {
  using Value = typename TextureOf<Base>::Value;

 public:
  ScaleTexture(const Base* tex, const FloatTexture* scale) : tex_(tex), scale_(scale) {}
  Value value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    float s = scale_->evaluate(ctx);
    // A zero scale masks the texture without evaluating it (as pbrt-v4 does).
    if (s == 0.f) return Value(0.f);
    return s * TextureOf<Base>::of(*tex_, ctx, lambda);
  }

 private:
  const Base* tex_;
  const FloatTexture* scale_;
};

}  // namespace

const PluginSpec& scale_texture_spec() {
  static const PluginSpec spec{
      "Texture",
      "tex × scale",
      "—",
      {param::any_texture("tex", 1).describe("of the texture's kind"), param::float_texture("scale", 1)}};
  return spec;
}

std::unique_ptr<FloatTexture> create_scale_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, scale_texture_spec(), "scale");
  return std::make_unique<ScaleTexture<FloatTexture>>(ctx.textures.float_param(p, "tex"),
                                                      ctx.textures.float_param(p, "scale"));
}

std::unique_ptr<SpectrumTexture> create_scale_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, scale_texture_spec(), "scale");
  return std::make_unique<ScaleTexture<SpectrumTexture>>(ctx.textures.spectrum_param(p, "tex"),
                                                         ctx.textures.float_param(p, "scale"));
}

}  // namespace eyetrace
