#include "textures/constant_texture.h"

namespace eyetrace {

const PluginSpec& constant_texture_spec() {
  static const PluginSpec spec{
      "Texture",
      "one value everywhere",
      "—",
      {param::float_or_spectrum("value", 1).describe("a float or a spectrum, of the texture's kind")}};
  return spec;
}

std::unique_ptr<FloatTexture> create_constant_float_texture(const TextureContext& ctx) {
  return std::make_unique<ConstantFloatTexture>(
      PluginParams(ctx.params, constant_texture_spec(), "constant").get_float("value"));
}

std::unique_ptr<SpectrumTexture> create_constant_spectrum_texture(const TextureContext& ctx) {
  const SpectrumValue v =
      PluginParams(ctx.params, constant_texture_spec(), "constant").get_spectrum("value", SpectrumType::Albedo);
  if (v.rgb) return std::make_unique<ConstantSpectrumTexture>(*v.rgb);
  return std::make_unique<ConstantSpectrumTexture>(v.spectrum);
}

}  // namespace eyetrace
