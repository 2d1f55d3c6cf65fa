// "scale", "mix" and "constant" textures: their arithmetic, defaults and references to
// named textures.
#include <gtest/gtest.h>

#include "../support/params.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include "core/transform.h"
#include "scene/texture_store.h"
#include "textures/checkerboard_texture.h"
#include "textures/constant_texture.h"
#include "textures/mix_texture.h"
#include "textures/scale_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr auto number = test::number_param;

Param texture_ref(const std::string& name, const std::string& tex) {
  Param p;
  p.type = "texture";
  p.name = name;
  p.strings = {tex};
  return p;
}

TEST(ConstantTexture, ValueAndDefault) {
  TextureStore store;
  ParameterList empty;
  EXPECT_EQ(create_constant_float_texture(TextureContext{empty, Transform(), store, ""})->evaluate({}), 1.f);
  const SampledWavelengths l = test::wavelengths();
  EXPECT_TRUE(
      test::same(create_constant_spectrum_texture(TextureContext{empty, Transform(), store, ""})->evaluate({}, l),
                 SampledSpectrum(1.f), 0.f));
  ParameterList p;
  p.add(number("rgb", "value", {0.1, 0.2, 0.3}));
  EXPECT_TRUE(test::same(create_constant_spectrum_texture(TextureContext{p, Transform(), store, ""})->evaluate({}, l),
                         test::albedo(RGB(0.1f, 0.2f, 0.3f), l), 0.f));
}

TEST(ScaleTexture, MultipliesTexByScale) {
  TextureStore store;
  store.add_float("half", std::make_unique<ConstantFloatTexture>(0.5f), SourceLoc{});
  ParameterList p;
  p.add(number("rgb", "tex", {0.2, 0.4, 0.8}));
  p.add(texture_ref("scale", "half"));
  auto t = create_scale_spectrum_texture(TextureContext{p, Transform(), store, ""});
  const SampledWavelengths l = test::wavelengths();
  EXPECT_TRUE(test::same(t->evaluate({}, l), 0.5f * test::albedo(RGB(0.2f, 0.4f, 0.8f), l), 1e-6f));
  ParameterList q;
  q.add(number("float", "tex", {3.0}));
  q.add(number("float", "scale", {-2.0}));
  EXPECT_FLOAT_EQ(create_scale_float_texture(TextureContext{q, Transform(), store, ""})->evaluate({}), -6.f);
  ParameterList defaults;
  EXPECT_FLOAT_EQ(create_scale_float_texture(TextureContext{defaults, Transform(), store, ""})->evaluate({}), 1.f);
}

TEST(MixTexture, LinearBlend) {
  TextureStore store;
  ParameterList p;
  p.add(number("float", "tex1", {2.0}));
  p.add(number("float", "tex2", {6.0}));
  p.add(number("float", "amount", {0.25}));
  EXPECT_FLOAT_EQ(create_mix_float_texture(TextureContext{p, Transform(), store, ""})->evaluate({}), 3.f);
  // Defaults: tex1 = 0, tex2 = 1, amount = 0.5.
  ParameterList d;
  EXPECT_FLOAT_EQ(create_mix_float_texture(TextureContext{d, Transform(), store, ""})->evaluate({}), 0.5f);
  ParameterList s;
  s.add(number("rgb", "tex1", {1, 0, 0}));
  s.add(number("rgb", "tex2", {0, 0, 1}));
  s.add(number("float", "amount", {0.75}));
  const SampledWavelengths l = test::wavelengths();
  EXPECT_TRUE(test::same(create_mix_spectrum_texture(TextureContext{s, Transform(), store, ""})->evaluate({}, l),
                         0.25f * test::albedo(RGB(1, 0, 0), l) + 0.75f * test::albedo(RGB(0, 0, 1), l), 1e-6f));
}

TEST(MixTexture, AmountFromATexture) {
  // A checkerboard as the amount selects tex1 on even squares and tex2 on odd ones.
  TextureStore store;
  ParameterList c;
  store.add_float("checks", create_checkerboard_float_texture(TextureContext{c, Transform(), store, ""}), SourceLoc{});
  ParameterList p;
  p.add(number("float", "tex1", {10.0}));
  p.add(number("float", "tex2", {20.0}));
  p.add(texture_ref("amount", "checks"));
  auto t = create_mix_float_texture(TextureContext{p, Transform(), store, ""});
  TextureEvalContext even, odd;
  even.uv = Vec2(0.5f, 0.5f);  // checks = 1 -> all tex2
  odd.uv = Vec2(1.5f, 0.5f);   // checks = 0 -> all tex1
  EXPECT_EQ(t->evaluate(even), 20.f);
  EXPECT_EQ(t->evaluate(odd), 10.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
