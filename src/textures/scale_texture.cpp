#include "textures/scale_texture.h"

#include "scene/texture_store.h"

namespace eyetrace {

namespace {

template <typename Base, typename Value>
class ScaleTexture final : public Base {
 public:
  ScaleTexture(const Base* tex, const FloatTexture* scale) : tex_(tex), scale_(scale) {}
  Value evaluate(const TextureEvalContext& ctx) const override {
    float s = scale_->evaluate(ctx);
    // A zero scale masks the texture without evaluating it (as pbrt-v4 does).
    if (s == 0.f) return Value(0.f);
    return s * tex_->evaluate(ctx);
  }

 private:
  const Base* tex_;
  const FloatTexture* scale_;
};

}  // namespace

std::unique_ptr<FloatTexture> create_scale_float_texture(const TextureContext& ctx) {
  const FloatTexture* tex = ctx.textures.float_param(ctx.params, "tex", 1.f);
  const FloatTexture* scale = ctx.textures.float_param(ctx.params, "scale", 1.f);
  return std::make_unique<ScaleTexture<FloatTexture, float>>(tex, scale);
}

std::unique_ptr<SpectrumTexture> create_scale_spectrum_texture(const TextureContext& ctx) {
  const SpectrumTexture* tex = ctx.textures.spectrum_param(ctx.params, "tex", RGB(1.f));
  const FloatTexture* scale = ctx.textures.float_param(ctx.params, "scale", 1.f);
  return std::make_unique<ScaleTexture<SpectrumTexture, RGB>>(tex, scale);
}

}  // namespace eyetrace
