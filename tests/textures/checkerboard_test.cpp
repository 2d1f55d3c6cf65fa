// The "checkerboard" texture: squares by parity of floor(s) + floor(t), the uv mapping
// parameters, the solid (3D) checker and the closed-form filtered average.
#include <gtest/gtest.h>

#include "../support/params.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include "core/transform.h"
#include "scene/texture_store.h"
#include "textures/checkerboard_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr auto number = test::number_param;

TextureEvalContext at_uv(float u, float v, float footprint = 0.f) {
  TextureEvalContext c;
  c.uv = Vec2(u, v);
  c.footprint = footprint;
  return c;
}

TEST(Checkerboard, DefaultsAndParity) {
  ParameterList p;
  TextureStore store;
  auto t = create_checkerboard_float_texture(TextureContext{p, Transform(), store, ""});
  // tex1 = 1 where floor(u) + floor(v) is even, tex2 = 0 where odd.
  EXPECT_EQ(t->evaluate(at_uv(0.5f, 0.5f)), 1.f);
  EXPECT_EQ(t->evaluate(at_uv(1.5f, 0.5f)), 0.f);
  EXPECT_EQ(t->evaluate(at_uv(1.5f, 1.5f)), 1.f);
  EXPECT_EQ(t->evaluate(at_uv(-0.5f, 0.5f)), 0.f);
  EXPECT_EQ(t->evaluate(at_uv(-0.5f, -0.5f)), 1.f);
}

TEST(Checkerboard, UvScaleAndDelta) {
  // s = 4 u + 0.5: u = 0.2 gives s = 1.3 (odd square), u = 0.3 gives s = 1.7 (odd), 0.4 -> 2.1.
  ParameterList p;
  p.add(number("float", "uscale", {4.0}));
  p.add(number("float", "vscale", {4.0}));
  p.add(number("float", "udelta", {0.5}));
  p.add(number("rgb", "tex1", {1, 0, 0}));
  p.add(number("rgb", "tex2", {0, 0, 1}));
  TextureStore store;
  auto t = create_checkerboard_spectrum_texture(TextureContext{p, Transform(), store, ""});
  const SampledWavelengths l = test::wavelengths();
  const SampledSpectrum red = test::albedo(RGB(1, 0, 0), l), blue = test::albedo(RGB(0, 0, 1), l);
  EXPECT_TRUE(test::same(t->evaluate(at_uv(0.2f, 0.1f), l), blue, 0.f));
  EXPECT_TRUE(test::same(t->evaluate(at_uv(0.4f, 0.1f), l), red, 0.f));
  EXPECT_TRUE(test::same(t->evaluate(at_uv(0.4f, 0.3f), l), blue, 0.f));
  for (const auto& param : p.params()) EXPECT_TRUE(param.used) << param.name;
}

TEST(Checkerboard, SolidCheckerInTextureSpace) {
  ParameterList p;
  p.add(number("integer", "dimension", {3}));
  TextureStore store;
  // Texture space is world space scaled by 1/2: cells are 2 world units wide.
  auto t = create_checkerboard_float_texture(TextureContext{p, scale(Vec3(2.f)), store, ""});
  TextureEvalContext c;
  c.p = Vec3(0.5f, 0.5f, 0.5f);
  EXPECT_EQ(t->evaluate(c), 1.f);
  c.p = Vec3(2.5f, 0.5f, 0.5f);
  EXPECT_EQ(t->evaluate(c), 0.f);
  c.p = Vec3(2.5f, 2.5f, 0.5f);
  EXPECT_EQ(t->evaluate(c), 1.f);
  c.p = Vec3(2.5f, 2.5f, -0.5f);
  EXPECT_EQ(t->evaluate(c), 0.f);
}

TEST(Checkerboard, FilteredValueIsTheLocalAverage) {
  // A filter much wider than a square sees half of each texture.
  EXPECT_NEAR(checkerboard_2d(Vec2(0.3f, 0.7f), 40.f), 0.5f, 0.02f);
  // A filter inside one square sees only it.
  EXPECT_EQ(checkerboard_2d(Vec2(0.5f, 0.5f), 0.1f), 0.f);
  // Centred on a vertical edge in s (inside one row in t): exactly half.
  EXPECT_NEAR(checkerboard_2d(Vec2(1.f, 0.5f), 0.2f), 0.5f, 1e-6f);
  // Independent check: a triangle filter of half-width h = 0.3 (1.5 x 0.2) centred at
  // s = 0.9 covers [0.6, 1.2]; the part beyond s = 1 has weight (0.2)^2 / (2 h^2) = 2/9.
  EXPECT_NEAR(checkerboard_2d(Vec2(0.9f, 0.5f), 0.2f), 2.f / 9.f, 1e-5f);
}

TEST(Checkerboard, BadDimensionIsAnError) {
  ParameterList p;
  p.add(number("integer", "dimension", {4}));
  TextureStore store;
  EXPECT_THROW(create_checkerboard_float_texture(TextureContext{p, Transform(), store, ""}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
