#include "textures/constant_texture.h"

namespace eyetrace {

std::unique_ptr<FloatTexture> create_constant_float_texture(const TextureContext& ctx) {
  return std::make_unique<ConstantFloatTexture>(ctx.params.get_float("value", 1.f));
}

std::unique_ptr<SpectrumTexture> create_constant_spectrum_texture(const TextureContext& ctx) {
  return std::make_unique<ConstantSpectrumTexture>(ctx.params.get_rgb("value").value_or(RGB(1.f)));
}

}  // namespace eyetrace
