// Texture interfaces: a value as a function of where on a surface we are.
#pragma once
#include "core/interaction.h"
#include "core/spectrum.h"

namespace eyetrace {

struct TextureEvalContext {
  Vec3 p{0.f};
  Vec3 n{0.f, 0.f, 1.f};
  Vec2 uv{0.f};
  float footprint = 0.f;  // approximate uv-space filter width (0: point sample)
  // What the material uses a spectrum texture's value as: textures holding RGB turn it into a
  // bounded reflectance spectrum or an unbounded one (an index of refraction) accordingly.
  SpectrumType spectrum_type = SpectrumType::Albedo;
  TextureEvalContext() = default;
  explicit TextureEvalContext(const SurfaceInteraction& si) : p(si.p), n(si.n), uv(si.uv), footprint(si.footprint) {}
};

class FloatTexture {
 public:
  virtual ~FloatTexture() = default;
  virtual float evaluate(const TextureEvalContext& ctx) const = 0;
};

// A spectrum-valued texture, evaluated at the sample's wavelengths. Textures holding RGB
// (constants, images) turn it into a spectrum of the type ctx.spectrum_type asks for.
class SpectrumTexture {
 public:
  virtual ~SpectrumTexture() = default;
  virtual SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const = 0;
};

// One value everywhere: what a plain material parameter ("rgb reflectance" [...]) becomes,
// and pbrt-v4's "constant" texture plugin. They live with the interfaces because the scene
// front end makes them for every constant parameter.
class ConstantFloatTexture final : public FloatTexture {
 public:
  explicit ConstantFloatTexture(float v) : v_(v) {}
  float evaluate(const TextureEvalContext&) const override { return v_; }

 private:
  float v_;
};

class ConstantSpectrumTexture final : public SpectrumTexture {
 public:
  // An RGB value: both readings made once here, not per evaluation.
  explicit ConstantSpectrumTexture(const RGB& rgb)
      : albedo_(Spectrum::from_rgb(rgb, SpectrumType::Albedo)),
        unbounded_(Spectrum::from_rgb(rgb, SpectrumType::Unbounded)) {}
  // A spectrum given as such reads the same either way.
  explicit ConstantSpectrumTexture(const Spectrum& s) : albedo_(s), unbounded_(s) {}
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    return (ctx.spectrum_type == SpectrumType::Albedo ? albedo_ : unbounded_).sample(lambda);
  }

 private:
  Spectrum albedo_, unbounded_;
};

}  // namespace eyetrace
