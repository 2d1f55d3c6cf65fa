// Lets one template serve a texture plugin's float and spectrum kinds although their
// evaluate() signatures differ (a spectrum texture also takes the sample's wavelengths):
// the template implements value(ctx, lambda) and derives from TextureOf<Base>.
#pragma once
#include "core/texture.h"

namespace eyetrace {

template <typename Base>
class TextureOf;

template <>
class TextureOf<FloatTexture> : public FloatTexture {
 public:
  using Value = float;
  float evaluate(const TextureEvalContext& ctx) const final { return value(ctx, SampledWavelengths()); }
  virtual float value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const = 0;
  static float of(const FloatTexture& t, const TextureEvalContext& ctx, const SampledWavelengths&) {
    return t.evaluate(ctx);
  }
};

template <>
class TextureOf<SpectrumTexture> : public SpectrumTexture {
 public:
  using Value = SampledSpectrum;
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const final {
    return value(ctx, lambda);
  }
  virtual SampledSpectrum value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const = 0;
  static SampledSpectrum of(const SpectrumTexture& t, const TextureEvalContext& ctx, const SampledWavelengths& l) {
    return t.evaluate(ctx, l);
  }
};

}  // namespace eyetrace
