// MakeNamedMedium "cloud": the density at fixed points against an independent double-precision
// evaluation of pbrt-v4's formula and noise (tests/data/media/cloud_density.py, its output pasted
// below), the coefficients scaled by it, the transform at MakeNamedMedium placing the box, and
// majorants confined to the box.
#include "media/cloud_medium.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/transform.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Medium> make_cloud(const std::string& params, const std::string& transform = "") {
  const std::string text = "WorldBegin\n" + transform + "\nMakeNamedMedium \"c\" \"string type\" \"cloud\" " + params;
  SceneDescription desc = parse_scene_string(text, "c.pbrt", ".");
  const TransformedEntity& e = desc.media.at("c");
  return create_cloud_medium(MediumContext{e.params, e.world_from_object});
}

const Vec3 kPoints[8] = {{0.13f, 0.62f, 0.41f}, {0.77f, 0.55f, 0.29f}, {0.5f, 0.9f, 0.5f}, {0.31f, 0.71f, 0.88f},
                         {0.92f, 0.58f, 0.07f}, {0.45f, 0.66f, 0.6f},  {0.2f, 0.8f, 0.3f}, {0.66f, 0.53f, 0.74f}};

struct Setting {
  float density, wispiness, frequency;
  double expected[8];  // cloud_density.py
};
const Setting kSettings[3] = {
    {1.f, 1.f, 5.f, {0.263517, 0.527628, 0.023066, 0.000000, 0.264584, 0.053728, 0.119626, 0.000000}},
    {2.f, 0.f, 3.f, {0.058804, 0.017637, 0.000000, 0.589175, 0.000000, 0.474534, 0.700945, 0.944142}},
    {1.5f, 2.f, 7.f, {0.000000, 0.000000, 0.038482, 0.216265, 0.223486, 0.000000, 0.000000, 0.000000}}};

TEST(CloudMedium, DensityMatchesAnIndependentEvaluationOfPbrtV4sFormula) {
  for (const Setting& s : kSettings) {
    const std::string params = fmt::format("\"float density\" {} \"float wispiness\" {} \"float frequency\" {}",
                                           s.density, s.wispiness, s.frequency);
    const auto m = make_cloud(params);
    const auto* cloud = dynamic_cast<const CloudMedium*>(m.get());
    ASSERT_NE(cloud, nullptr);
    for (int i = 0; i < 8; ++i)
      EXPECT_NEAR(cloud->density_in_medium_space(kPoints[i]), s.expected[i], 2e-4) << params << " point " << i;
  }
}

// Below y = 0.5 the cloud fills in: 2 (0.5 - y) >= 1 at y <= 0 whatever the noise.
TEST(CloudMedium, IsSolidAtTheBottomOfItsBox) {
  const auto m = make_cloud("");
  const auto* cloud = dynamic_cast<const CloudMedium*>(m.get());
  for (float x : {0.1f, 0.5f, 0.9f}) EXPECT_FLOAT_EQ(cloud->density_in_medium_space(Vec3(x, 0.f, 0.3f)), 1.f);
}

TEST(CloudMedium, CoefficientsScaleWithTheDensityAndTheTransformPlacesTheBox) {
  const auto m = make_cloud("\"rgb sigma_a\" [0.5 0.5 0.5] \"rgb sigma_s\" [3 3 3]", "Translate 10 0 0\nScale 2 2 2");
  const auto* cloud = dynamic_cast<const CloudMedium*>(m.get());
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.3f, 400.f, 700.f);
  // Render-space (10 + 2x, 2y, 2z) is medium-space (x, y, z).
  const Vec3 p_medium = kPoints[1];
  const float d = cloud->density_in_medium_space(p_medium);
  ASSERT_GT(d, 0.1f);
  const MediumProperties mp = m->properties(Vec3(10.f, 0.f, 0.f) + 2.f * p_medium, lambda);
  EXPECT_NEAR(mp.sigma_a[0], 0.5f * d, 1e-3f);
  EXPECT_NEAR(mp.sigma_s[0], 3.f * d, 5e-3f);
  // One majorant segment, sigma_a + sigma_s, over the box only: x from 10 to 12 along +x.
  MajorantIterator it = m->majorants(Ray{Vec3(0.f, 1.f, 1.f), Vec3(1.f, 0.f, 0.f)}, 100.f, lambda);
  const auto seg = it.next();
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->t_min, 10.f, 1e-4f);
  EXPECT_NEAR(seg->t_max, 12.f, 1e-4f);
  EXPECT_NEAR(seg->sigma_maj[0], 3.5f, 1e-3f);
  EXPECT_FALSE(it.next());
  EXPECT_FALSE(m->majorants(Ray{Vec3(0.f, 5.f, 1.f), Vec3(1.f, 0.f, 0.f)}, 100.f, lambda).next());  // misses
}

TEST(CloudMedium, BadInputIsAnErrorNamingFileLineAndParameter) {
  auto error = [](const std::string& params) -> std::string {
    try {
      make_cloud(params);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  for (auto [params, name] :
       {std::pair{"\"float density\" -1", "density"}, std::pair{"\"float g\" 1", "\"g\""},
        std::pair{"\"point3 p1\" [1 0 1]", "p1"}, std::pair{"\"rgb sigma_s\" [1 -1 1]", "sigma_s"}}) {
    const std::string e = error(params);
    EXPECT_NE(e.find("c.pbrt:3"), std::string::npos) << e;
    EXPECT_NE(e.find(name), std::string::npos) << e;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
