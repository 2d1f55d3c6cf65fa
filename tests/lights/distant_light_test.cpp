// Distant light: light travels from "from" to "to"; a patch with normal n receives
// E = L max(0, n . w_to_light); "illuminance" sets E on a patch facing the light; the
// shadow-ray end lies beyond the scene, and power is the flux through its bounding disc.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "light_test_util.h"
#include "lights/distant_light.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Light> make_distant(std::vector<Param> ps, const Transform& t = Transform()) {
  ParameterList params = make_params(std::move(ps));
  return create_distant_light(LightContext{params, t, ""});
}

TEST(DistantLight, DefaultLightTravelsAlongPlusZ) {
  auto light = make_distant({});
  const SampledWavelengths lambda = test::wavelengths();
  auto s = light->sample_li(LightSampleContext{Vec3(0), Vec3(0, 0, -1)}, Vec2(0.5f), lambda);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->wi.z, -1.f, 1e-6f);  // towards the light: against the travel direction
  EXPECT_TRUE(test::same(s->L, test::emission(1.f, lambda)));
  EXPECT_EQ(s->pdf, 1.f);
}

TEST(DistantLight, IrradianceIsLTimesCosine) {
  auto light = make_distant({rgb_param("L", 2, 4, 6), point_param("from", 1, 1, 1), point_param("to", 0, 0, 0)});
  Vec3 to_light = glm::normalize(Vec3(1, 1, 1));
  for (Vec3 n : {Vec3(0, 0, 1), Vec3(1, 0, 0), glm::normalize(Vec3(1, 1, 1)), glm::normalize(Vec3(-1, 2, 0.3f))}) {
    const LightSampleContext ctx{Vec3(0.5f, -2, 3), n};
    auto s = light->sample_li(ctx, Vec2(0.1f, 0.9f), test::wavelengths());
    ASSERT_TRUE(s.has_value());
    float E = sample_luminance(*light, ctx, Vec2(0.1f, 0.9f)) * std::max(0.f, glm::dot(n, s->wi)) / s->pdf;
    // Luminance of the upsampled spectrum matches the RGB's within 1e-3 (the table's accuracy).
    const float expected = luminance(RGB(2, 4, 6)) * std::max(0.f, glm::dot(n, to_light));
    EXPECT_NEAR(E, expected, 1e-3f * expected + 1e-6f);
  }
}

TEST(DistantLight, TransformTurnsTheDirection) {
  // Default travel +z; rotating 90 degrees about +y turns it into +x travel.
  auto light = make_distant({}, rotate(90.f, Vec3(0, 1, 0)));
  auto s = light->sample_li(LightSampleContext{Vec3(0), Vec3(0)}, Vec2(0.5f), test::wavelengths());
  EXPECT_NEAR(s->wi.x, -1.f, 1e-6f);
}

TEST(DistantLight, IlluminanceSetsPerpendicularIrradiance) {
  auto light = make_distant({float_param("illuminance", 5), rgb_param("L", 3, 3, 3)});
  EXPECT_NEAR(sample_luminance(*light, LightSampleContext{Vec3(0), Vec3(0, 0, -1)}, Vec2(0.5f)), 5.f, 5e-3f);
  auto scaled = make_distant({float_param("illuminance", 5), float_param("scale", 0.5)});
  EXPECT_NEAR(sample_luminance(*scaled, LightSampleContext{Vec3(0), Vec3(0, 0, -1)}, Vec2(0.5f)), 2.5f, 2.5e-3f);
  EXPECT_THROW(make_distant({float_param("illuminance", 0)}), SceneError);
}

TEST(DistantLight, ShadowRayEndsOutsideTheSceneAndPowerCoversIt) {
  auto light = make_distant({rgb_param("L", 2, 2, 2)});
  Bounds3 b;
  b.extend(Vec3(-3, -4, 0));
  b.extend(Vec3(3, 4, 0));  // radius 5
  light->preprocess(b);
  Vec3 p(1, 1, 0);
  auto s = light->sample_li(LightSampleContext{p, Vec3(0)}, Vec2(0.5f), test::wavelengths());
  EXPECT_NEAR(glm::distance(s->p_light, p), 10.f, 1e-4f);
  EXPECT_NEAR(light->power(), kPi * 25.f * 2.f, 1e-3f);
}

TEST(DistantLight, CoincidentFromAndToIsAnError) {
  try {
    make_distant({point_param("from", 1, 2, 3), point_param("to", 1, 2, 3)});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"to\""), std::string::npos) << e.what();
  }
}

// Light paths: rays along the light's direction through the disc that bounds the scene, from
// outside the scene's bounding sphere, carrying pi r^2 L (the light's power).
TEST(DistantLight, SampleLeRaysCrossTheSceneDiscAndCarryThePower) {
  auto light = make_distant({rgb_param("L", 2, 2, 2), point_param("from", 0, 0, 0), point_param("to", 0, 0, 1)});
  Bounds3 b;
  b.extend(Vec3(-1, -2, -1));
  b.extend(Vec3(3, 2, 1));
  light->preprocess(b);
  const Vec3 c = b.center();
  const float r = b.radius();
  const LeEstimate e = sample_le_power(*light, 4000, 7, false, [&](const LightLeSample& s) {
    EXPECT_NEAR(glm::distance(s.ray.d, Vec3(0, 0, 1)), 0.f, 1e-6f);
    EXPECT_GE(glm::distance(s.ray.o, c), r * (1 - 1e-5f));  // starts outside the scene
    // Where it crosses the plane through the centre: within the disc.
    const Vec3 at = s.ray.o + (c.z - s.ray.o.z) * s.ray.d;
    EXPECT_LE(glm::distance(at, c), r * (1 + 1e-5f));
  });
  EXPECT_EQ(e.samples, 4000);
  EXPECT_NEAR(e.power, kPi * r * r * 2, 1e-3 * e.power);
  EXPECT_NEAR(e.power, light->power(), 1e-3 * e.power);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
