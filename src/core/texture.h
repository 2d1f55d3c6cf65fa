// Texture interfaces: a value as a function of where on a surface we are.
#pragma once
#include "core/interaction.h"

namespace eyetrace {

struct TextureEvalContext {
  Vec3 p{0.f};
  Vec3 n{0.f, 0.f, 1.f};
  Vec2 uv{0.f};
  float footprint = 0.f;  // approximate uv-space filter width (0: point sample)
  TextureEvalContext() = default;
  explicit TextureEvalContext(const SurfaceInteraction& si) : p(si.p), n(si.n), uv(si.uv), footprint(si.footprint) {}
};

class FloatTexture {
 public:
  virtual ~FloatTexture() = default;
  virtual float evaluate(const TextureEvalContext& ctx) const = 0;
};

class SpectrumTexture {
 public:
  virtual ~SpectrumTexture() = default;
  virtual RGB evaluate(const TextureEvalContext& ctx) const = 0;
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
  explicit ConstantSpectrumTexture(const RGB& v) : v_(v) {}
  RGB evaluate(const TextureEvalContext&) const override { return v_; }

 private:
  RGB v_;
};

}  // namespace eyetrace
