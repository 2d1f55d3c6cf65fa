// Point light: irradiance follows the inverse-square law E = I / r^2, "from" is placed by
// the light's transform, and "power" sets the total power 4 pi I (pbrt-v4 semantics, with
// "scale" multiplying on top).
#include <gtest/gtest.h>

#include "core/error.h"
#include "light_test_util.h"
#include "lights/point_light.h"

namespace eyetrace {
namespace {

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

// Photons (sample_le): every ray leaves "from", directions uniform over the sphere (their mean
// is 0 within 4 standard errors, each component's variance being 1/3), and each photon carries
// exactly the power 4 pi I.
TEST(PointLight, PhotonsLeaveFromTheLightUniformlyCarryingFourPiI) {
  auto light = make_point({rgb_param("I", 2, 3, 4), point_param("from", 1, 2, 3)});
  const SampledWavelengths lambda = test::wavelengths();
  const float I = test::emission(RGB(2, 3, 4), lambda)[0];
  const int n = 20000;
  Vec3 mean_dir(0.f);
  const FluxEstimate flux = photon_flux(*light, lambda, I, n, 7, [&](const LightLeSample& s) {
    EXPECT_NEAR(glm::distance(s.ray.o, Vec3(1, 2, 3)), 0.f, 1e-6f);
    EXPECT_NEAR(glm::length(s.ray.d), 1.f, 1e-5f);
    mean_dir += s.ray.d / float(n);
  });
  EXPECT_NEAR(flux.mean, 4.0 * kPiDouble, 1e-4);
  EXPECT_LT(flux.std_error, 1e-5);
  EXPECT_LT(glm::length(mean_dir), 4.f * std::sqrt(3.f / (3.f * n)));
}

}  // namespace
}  // namespace eyetrace
