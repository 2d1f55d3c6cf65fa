// The "directionmix" texture against pbrt-v4's definition: |n . dir| tex1 + (1 - |n . dir|) tex2,
// dir taken through the texture's transform and normalised, default (0, 1, 0), defaults tex1 0
// and tex2 1; spectra alike; a zero direction is an error naming "dir".
#include <gtest/gtest.h>

#include <cmath>

#include "../support/params.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"
#include "core/error.h"
#include "core/transform.h"
#include "scene/texture_store.h"
#include "textures/direction_mix_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr auto number = test::number_param;

TextureEvalContext facing(Vec3 n) {
  TextureEvalContext c;
  c.n = glm::normalize(n);
  return c;
}

TEST(DirectionMixTexture, WeightsByTheCosineToDir) {
  ParameterList params;
  params.add(number("float", "tex1", {3}));
  params.add(number("float", "tex2", {-1}));
  TextureStore store;
  auto tex = create_directionmix_float_texture(TextureContext{params, Transform(), store, ""});
  EXPECT_FLOAT_EQ(tex->evaluate(facing(Vec3(0, 1, 0))), 3.f);   // faces dir = +y
  EXPECT_FLOAT_EQ(tex->evaluate(facing(Vec3(0, -1, 0))), 3.f);  // |n . dir|: either side
  EXPECT_FLOAT_EQ(tex->evaluate(facing(Vec3(1, 0, 0))), -1.f);  // edge-on
  const float a = std::cos(0.6f);
  EXPECT_NEAR(tex->evaluate(facing(Vec3(std::sin(0.6f), std::cos(0.6f), 0))), a * 3.f + (1 - a) * -1.f, 1e-6f);
}

TEST(DirectionMixTexture, DirGoesThroughTheTransformAndDefaultsHold) {
  ParameterList params;
  params.add(number("vector3", "dir", {0, 0, 2}));
  TextureStore store;
  // Rotating the texture space 90 degrees about x turns (0, 0, 1) into (0, -1, 0).
  auto tex = create_directionmix_float_texture(TextureContext{params, rotate(90.f, Vec3(1, 0, 0)), store, ""});
  EXPECT_NEAR(tex->evaluate(facing(Vec3(0, 1, 0))), 0.f, 1e-6f);  // tex1 default 0
  EXPECT_NEAR(tex->evaluate(facing(Vec3(0, 0, 1))), 1.f, 1e-6f);  // tex2 default 1
  ParameterList none;
  auto plain = create_directionmix_float_texture(TextureContext{none, Transform(), store, ""});
  EXPECT_NEAR(plain->evaluate(facing(Vec3(0, 1, 0))), 0.f, 1e-6f);
  const SampledWavelengths l = test::wavelengths();
  auto spectral = create_directionmix_spectrum_texture(TextureContext{none, Transform(), store, ""});
  const SampledSpectrum s = spectral->evaluate(facing(Vec3(1, 1, 0)), l);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(s[i], 1.f - std::sqrt(0.5f), 1e-5f);
}

TEST(DirectionMixTexture, ZeroDirIsAnError) {
  ParameterList params;
  params.add(number("vector3", "dir", {0, 0, 0}));
  TextureStore store;
  try {
    create_directionmix_float_texture(TextureContext{params, Transform(), store, ""});
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"dir\""), std::string::npos) << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
