// Point light: irradiance follows the inverse-square law E = I / r^2, "from" is placed by
// the light's transform, and "power" sets the total power 4 pi I (pbrt-v4 semantics, with
// "scale" multiplying on top).
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "light_test_util.h"
#include "lights/point_light.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Light> make_point(std::vector<Param> ps, const Transform& t = Transform()) {
  ParameterList params = make_params(std::move(ps));
  return create_point_light(LightContext{params, t, ""});
}

TEST(PointLight, IrradianceFollowsInverseSquareLaw) {
  auto light = make_point({rgb_param("I", 2, 3, 4), point_param("from", 1, 2, 3)}, translate(Vec3(0, 0, 5)));
  Vec3 pos(1, 2, 8);
  Vec3 dir = glm::normalize(Vec3(1, -2, 0.5f));
  for (float r : {0.5f, 2.f, 10.f, 300.f}) {
    LightSampleContext ctx{pos + r * dir, -dir};  // a patch facing the light
    const SampledWavelengths lambda = test::wavelengths();
    auto s = light->sample_li(ctx, Vec2(0.3f, 0.7f), lambda);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->pdf, 1.f);
    EXPECT_NEAR(glm::distance(s->p_light, pos), 0.f, 1e-5f);
    EXPECT_NEAR(glm::dot(s->wi, -dir), 1.f, 1e-6f);
    SampledSpectrum E = s->L * glm::dot(ctx.n, s->wi) / s->pdf;
    EXPECT_TRUE(test::same(E, test::emission(RGB(2, 3, 4), lambda) / (r * r), 1e-5f));
  }
  EXPECT_TRUE(light->is_delta());
  EXPECT_EQ(light->pdf_li(LightSampleContext{}, Vec3(0, 0, 1), nullptr), 0.f);
}

TEST(PointLight, DefaultsAreWhiteAtOrigin) {
  auto light = make_point({});
  const SampledWavelengths lambda = test::wavelengths();
  auto s = light->sample_li(LightSampleContext{Vec3(0, 0, 2), Vec3(0)}, Vec2(0.5f), lambda);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(test::same(s->L, test::emission(0.25f, lambda), 1e-6f));
  EXPECT_NEAR(light->power(), 4.f * kPi, 1e-5f);
}

TEST(PointLight, AtTheLightNoSample) {
  auto light = make_point({});
  EXPECT_FALSE(light->sample_li(LightSampleContext{Vec3(0), Vec3(0)}, Vec2(0.5f), test::wavelengths()).has_value());
}

TEST(PointLight, PowerParameterSetsTotalPower) {
  auto light = make_point({float_param("power", 100)});
  EXPECT_NEAR(light->power(), 100.f, 1e-3f);
  // Independently: a sphere of radius 2 around the light catches 4 pi r^2 * I / r^2.
  const float L = sample_luminance(*light, LightSampleContext{Vec3(2, 0, 0), Vec3(0)}, Vec2(0.5f));
  EXPECT_NEAR(L * 4.f * kPi * 4.f, 100.f, 0.2f);
  // pbrt-v4 normalises the spectrum's luminance, then applies "scale".
  auto scaled = make_point({float_param("power", 100), float_param("scale", 2), rgb_param("I", 5, 5, 5)});
  EXPECT_NEAR(scaled->power(), 200.f, 2e-3f);
}

TEST(PointLight, NegativeIntensityIsAnError) {
  try {
    make_point({rgb_param("I", 1, -1, 1)});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"I\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test.pbrt:3:7"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make_point({float_param("power", -5)}), SceneError);
  EXPECT_THROW(make_point({float_param("scale", -1)}), SceneError);
}

// Light paths: sample_le's rays from the point carry 4 pi I in total, uniformly over the sphere
// (every sample estimates it exactly), with the densities pdf_le gives.
TEST(PointLight, SampleLeRaysCarryThePower) {
  auto light = make_point({rgb_param("I", 3, 3, 3), point_param("from", 1, 2, 3)});
  Vec3 mean_dir(0.f);
  const LeEstimate e = sample_le_power(*light, 4000, 5, true, [&](const LightLeSample& s) {
    EXPECT_EQ(s.ray.o, Vec3(1, 2, 3));
    EXPECT_EQ(s.pdf_pos, 1.f);
    mean_dir += s.ray.d / 4000.f;
  });
  EXPECT_EQ(e.samples, 4000);
  EXPECT_NEAR(e.power, 4 * kPi * 3, 1e-3);
  EXPECT_NEAR(e.power, light->power(), 1e-3);
  EXPECT_LT(glm::length(mean_dir), 5 * std::sqrt(1.0 / 3 / 4000) * std::sqrt(3.0));  // isotropic: about 0
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
