// Spot light: full intensity inside coneangle - conedeltaangle, pbrt-v4's smoothstep in
// cos(theta) across the falloff band, zero outside; power 2 pi I (1 - (cos_start + cos_end) / 2)
// checked against a numerical integral of the intensity over the sphere.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "light_test_util.h"
#include "lights/spot_light.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Light> make_spot(std::vector<Param> ps, const Transform& t = Transform()) {
  ParameterList params = make_params(std::move(ps));
  return create_spot_light(LightContext{params, t, ""});
}

// A grey spectrum's value relative to the white emission (the RGB grey level it stands for).
float grey(const SampledSpectrum& s) { return s[1] / test::emission(1.f, test::wavelengths())[1]; }

// Irradiance at distance 1 along a direction theta degrees off the +x axis (in the xy plane).
float intensity_at(const Light& light, const Vec3& apex, float theta_deg) {
  float t = radians(theta_deg);
  Vec3 p = apex + Vec3(std::cos(t), std::sin(t), 0.f);
  const SampledWavelengths lambda = test::wavelengths();
  auto s = light.sample_li(LightSampleContext{p, Vec3(0)}, Vec2(0.5f), lambda);
  return s ? s->L[1] / test::emission(1.f, lambda)[1] : 0.f;  // at distance 1, L = I (grey)
}

TEST(SpotLight, FalloffAtConeEdgesIsSmoothstep) {
  // Axis +x; full within 20 degrees, zero beyond 30.
  auto light = make_spot({rgb_param("I", 7, 7, 7), point_param("from", 1, 1, 0), point_param("to", 2, 1, 0),
                          float_param("coneangle", 30), float_param("conedeltaangle", 10)});
  Vec3 apex(1, 1, 0);
  float cs = std::cos(radians(20.f)), ce = std::cos(radians(30.f));
  auto analytic = [&](float theta) {
    float t = std::clamp((std::cos(radians(theta)) - ce) / (cs - ce), 0.f, 1.f);
    return 7.f * t * t * (3.f - 2.f * t);
  };
  EXPECT_NEAR(intensity_at(*light, apex, 0.f), 7.f, 1e-5f);
  EXPECT_NEAR(intensity_at(*light, apex, 19.9f), 7.f, 1e-5f);
  EXPECT_NEAR(intensity_at(*light, apex, 20.f), 7.f, 1e-3f);
  for (float theta : {21.f, 23.f, 25.f, 27.f, 29.f})
    EXPECT_NEAR(intensity_at(*light, apex, theta), analytic(theta), 1e-4f);
  // Half intensity where cos(theta) is midway between the edges (smoothstep is symmetric).
  float mid = std::acos(0.5f * (cs + ce)) * 180.f / kPi;
  EXPECT_NEAR(intensity_at(*light, apex, mid), 3.5f, 1e-3f);
  EXPECT_NEAR(intensity_at(*light, apex, 30.f), 0.f, 1e-4f);
  EXPECT_EQ(intensity_at(*light, apex, 31.f), 0.f);
  EXPECT_EQ(intensity_at(*light, apex, 180.f), 0.f);
}

TEST(SpotLight, DefaultsPointAlongPlusZWithThirtyDegreeCone) {
  auto light = make_spot({});
  const SampledWavelengths lambda = test::wavelengths();
  auto s = light->sample_li(LightSampleContext{Vec3(0, 0, 2), Vec3(0)}, Vec2(0.5f), lambda);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(test::same(s->L, test::emission(0.25f, lambda), 1e-6f));
  float t31 = radians(31.f);
  EXPECT_FALSE(light->sample_li(LightSampleContext{Vec3(std::sin(t31), 0, std::cos(t31)), Vec3(0)}, Vec2(0.5f),
                                test::wavelengths()));
  EXPECT_FALSE(light->sample_li(LightSampleContext{Vec3(0, 0, -2), Vec3(0)}, Vec2(0.5f), test::wavelengths()));
}

TEST(SpotLight, TransformMovesAndTurnsTheCone) {
  // -90 degrees about x turns +z onto +y; then up by 3.
  auto light = make_spot({}, translate(Vec3(0, 3, 0)) * rotate(-90.f, Vec3(1, 0, 0)));
  const SampledWavelengths lambda = test::wavelengths();
  auto s = light->sample_li(LightSampleContext{Vec3(0, 5, 0), Vec3(0)}, Vec2(0.5f), lambda);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(test::same(s->L, test::emission(0.25f, lambda), 1e-5f));
  EXPECT_NEAR(glm::distance(s->p_light, Vec3(0, 3, 0)), 0.f, 1e-5f);
  EXPECT_FALSE(light->sample_li(LightSampleContext{Vec3(0, 3, 2), Vec3(0)}, Vec2(0.5f), test::wavelengths()));
}

// Power by midpoint quadrature of I(theta) 2 pi sin(theta) d(theta).
double integrated_power(const SpotLight& light) {
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double theta = (i + 0.5) * kPi / n;
    Vec3 w(0.f, float(std::sin(theta)), float(std::cos(theta)));
    sum += grey(light.intensity(w, test::wavelengths())) * 2.0 * kPi * std::sin(theta) * (kPi / n);
  }
  return sum;
}

TEST(SpotLight, PowerMatchesIntegratedIntensity) {
  auto light = make_spot({rgb_param("I", 3, 3, 3), float_param("coneangle", 40), float_param("conedeltaangle", 15)});
  const auto& spot = dynamic_cast<const SpotLight&>(*light);
  double numeric = integrated_power(spot);
  EXPECT_NEAR(light->power(), numeric, 1e-4 * numeric);
  auto normalised =
      make_spot({float_param("power", 50), float_param("coneangle", 40), float_param("conedeltaangle", 15)});
  EXPECT_NEAR(integrated_power(dynamic_cast<const SpotLight&>(*normalised)), 50.0, 5e-3);
}

TEST(SpotLight, BadParametersAreErrors) {
  EXPECT_THROW(make_spot({float_param("coneangle", 200)}), SceneError);
  EXPECT_THROW(make_spot({point_param("from", 1, 1, 1), point_param("to", 1, 1, 1)}), SceneError);
}

TEST(SpotLight, DeltaLargerThanConeWarnsAndFallsOffFromTheAxis) {
  int before = warning_count();
  set_warnings_enabled(false);
  auto light = make_spot({float_param("coneangle", 10), float_param("conedeltaangle", 12)});
  set_warnings_enabled(true);
  EXPECT_EQ(warning_count(), before + 1);
  const auto& spot = dynamic_cast<const SpotLight&>(*light);
  EXPECT_FLOAT_EQ(grey(spot.intensity(Vec3(0, 0, 1), test::wavelengths())), 1.f);
  float t5 = radians(5.f);
  float i5 = grey(spot.intensity(Vec3(std::sin(t5), 0, std::cos(t5)), test::wavelengths()));
  EXPECT_GT(i5, 0.f);
  EXPECT_LT(i5, 1.f);
}

// Light paths: sample_le's rays stay in the cone and carry the spot's power (the closed form
// checked above against a numerical integral), within 5 standard errors.
TEST(SpotLight, SampleLeRaysCarryThePower) {
  auto light = make_spot({rgb_param("I", 3, 3, 3), float_param("coneangle", 40), float_param("conedeltaangle", 15)},
                         translate(Vec3(0, 3, 0)) * rotate(-90.f, Vec3(1, 0, 0)));
  const float cos_cone = std::cos(radians(40.f));
  const LeEstimate e = sample_le_power(*light, 20000, 6, true, [&](const LightLeSample& s) {
    // Pointing along +y after the rotation (the default +z axis turned by -90 degrees about x).
    EXPECT_GE(glm::dot(s.ray.d, Vec3(0, 1, 0)), cos_cone - 1e-5f);
    EXPECT_NEAR(glm::distance(s.ray.o, Vec3(0, 3, 0)), 0.f, 1e-5f);
  });
  EXPECT_GT(e.samples, 19000);  // only the cone's rim, where the falloff is 0, returns nothing
  EXPECT_NEAR(e.power, light->power(), 5 * e.std_error + 1e-6);
  EXPECT_LT(e.std_error, 0.02 * light->power());
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
