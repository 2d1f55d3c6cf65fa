// Spot light: full intensity inside coneangle - conedeltaangle, pbrt-v4's smoothstep in
// cos(theta) across the falloff band, zero outside; power 2 pi I (1 - (cos_start + cos_end) / 2)
// checked against a numerical integral of the intensity over the sphere.
#include <gtest/gtest.h>

#include "core/error.h"
#include "light_test_util.h"
#include "lights/spot_light.h"

namespace eyetrace {
namespace {

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

// Photons (sample_le) leave the apex within the cone, and carry on average the spot's power:
// I times the cone's solid angle with the smoothstep falloff counting half its band,
// 2 pi (1 - (cos 20 + cos 30) / 2) (the smoothstep is symmetric about the band's middle). 4
// standard errors.
TEST(SpotLight, PhotonsStayInTheConeAndCarryItsPower) {
  auto light = make_spot({rgb_param("I", 5, 5, 5), point_param("from", 1, 1, 0), point_param("to", 1, 1, 2),
                          float_param("coneangle", 30), float_param("conedeltaangle", 10)});
  const SampledWavelengths lambda = test::wavelengths();
  const float I = test::emission(RGB(5), lambda)[0];
  const double cos30 = std::cos(kPiDouble / 6), cos20 = std::cos(kPiDouble / 9);
  const FluxEstimate flux = photon_flux(*light, lambda, I, 40000, 11, [&](const LightLeSample& s) {
    EXPECT_NEAR(glm::distance(s.ray.o, Vec3(1, 1, 0)), 0.f, 1e-6f);
    EXPECT_GE(s.ray.d.z, float(cos30) - 1e-5f);
  });
  const double expected = 2 * kPiDouble * (1 - 0.5 * (cos20 + cos30));
  EXPECT_NEAR(flux.mean, expected, 4 * flux.std_error + 1e-6);
}

}  // namespace
}  // namespace eyetrace
