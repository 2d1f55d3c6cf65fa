// A texture with one value everywhere: pbrt-v4's "constant" texture ("value", default 1),
// and what plain material parameters ("rgb reflectance" [...]) become.
#pragma once
#include <memory>

#include "core/registry.h"
#include "core/texture.h"

namespace eyetrace {

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

std::unique_ptr<FloatTexture> create_constant_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_constant_spectrum_texture(const TextureContext& ctx);

}  // namespace eyetrace
