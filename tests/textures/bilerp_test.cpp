// The "bilerp" texture against pbrt-v4's definition: (1-s)(1-t) v00 + s(1-t) v10 + (1-s)t v01
// + s t v11, its defaults (0, 0, 1, 1: the value is t), the uv mapping's scale and offset, and
// RGB corners read as reflectances.
#include <gtest/gtest.h>

#include "../support/params.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include "core/transform.h"
#include "scene/texture_store.h"
#include "textures/bilerp_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr auto number = test::number_param;

TextureEvalContext at(float u, float v) {
  TextureEvalContext c;
  c.uv = Vec2(u, v);
  return c;
}

TEST(BilerpTexture, InterpolatesTheCornersAsPbrtV4) {
  ParameterList params;
  params.add(number("float", "v00", {1}));
  params.add(number("float", "v10", {3}));
  params.add(number("float", "v01", {-2}));
  params.add(number("float", "v11", {7}));
  TextureStore store;
  auto tex = create_bilerp_float_texture(TextureContext{params, Transform(), store, ""});
  for (float u : {0.f, 0.25f, 0.5f, 1.f, 1.5f})
    for (float v : {0.f, 0.3f, 1.f, -0.5f}) {
      const double expected = (1 - u) * (1 - v) * 1.0 + u * (1 - v) * 3.0 + (1 - u) * v * -2.0 + u * v * 7.0;
      EXPECT_NEAR(tex->evaluate(at(u, v)), expected, 1e-5) << u << " " << v;
    }
}

TEST(BilerpTexture, DefaultsGiveTAndTheMappingApplies) {
  ParameterList empty;
  TextureStore store;
  auto plain = create_bilerp_float_texture(TextureContext{empty, Transform(), store, ""});
  EXPECT_FLOAT_EQ(plain->evaluate(at(0.7f, 0.25f)), 0.25f);
  ParameterList mapped;
  mapped.add(number("float", "vscale", {2}));
  mapped.add(number("float", "vdelta", {0.1}));
  auto scaled = create_bilerp_float_texture(TextureContext{mapped, Transform(), store, ""});
  EXPECT_NEAR(scaled->evaluate(at(0.7f, 0.25f)), 2 * 0.25 + 0.1, 1e-6);
}

TEST(BilerpTexture, SpectrumCornersAreReflectances) {
  ParameterList params;
  params.add(number("rgb", "v00", {0.2, 0.2, 0.2}));
  params.add(number("rgb", "v10", {0.6, 0.6, 0.6}));
  params.add(number("rgb", "v01", {0.2, 0.2, 0.2}));
  params.add(number("rgb", "v11", {0.6, 0.6, 0.6}));
  TextureStore store;
  auto tex = create_bilerp_spectrum_texture(TextureContext{params, Transform(), store, ""});
  const SampledWavelengths l = test::wavelengths();
  // A grey reflectance is flat in wavelength: halfway in s is 0.4 at every wavelength.
  const SampledSpectrum s = tex->evaluate(at(0.5f, 0.9f), l);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(s[i], 0.4f, 2e-3f) << i;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
