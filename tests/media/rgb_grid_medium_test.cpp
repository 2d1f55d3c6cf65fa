// MakeNamedMedium "rgbgrid": at a sample's centre the coefficients are that sample's RGB as an
// unbounded spectrum (the same spectrum a homogeneous medium makes of that RGB) times "scale",
// absent ones are 1; the emission is the RGB illuminant times Lescale; the majorants bound
// sigma_t at random points along random rays; bad input is an error naming file, line and
// parameter.
#include "media/rgb_grid_medium.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "media/homogeneous_medium.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Medium> make(const std::string& type, const std::string& params) {
  const std::string text = "WorldBegin\nMakeNamedMedium \"m\" \"string type\" \"" + type + "\" " + params;
  SceneDescription desc = parse_scene_string(text, "r.pbrt", ".");
  const TransformedEntity& e = desc.media.at("m");
  const MediumContext ctx{e.params, e.world_from_object};
  return type == "rgbgrid" ? create_rgb_grid_medium(ctx) : create_homogeneous_medium(ctx);
}

TEST(RGBGridMedium, SampleCentresCarryTheirRgbSpectraTimesScale) {
  // 2 x 1 x 1 over [0, 1]^3: sample centres at x = 0.25 and 0.75 (y = z = 0.5).
  const auto m = make("rgbgrid", "\"integer nx\" 2 \"rgb sigma_a\" [0.2 0.5 1.5  3 0.1 0.1] \"float scale\" 2");
  const auto left = make("homogeneous", "\"rgb sigma_a\" [0.2 0.5 1.5] \"float scale\" 2");
  const auto right = make("homogeneous", "\"rgb sigma_a\" [3 0.1 0.1] \"float scale\" 2");
  for (float u : {0.1f, 0.5f, 0.9f}) {
    const SampledWavelengths lambda = SampledWavelengths::sample_uniform(u);
    const MediumProperties a = m->properties(Vec3(0.25f, 0.5f, 0.5f), lambda);
    const MediumProperties b = m->properties(Vec3(0.75f, 0.5f, 0.5f), lambda);
    const MediumProperties mid = m->properties(Vec3(0.5f, 0.5f, 0.5f), lambda);
    const MediumProperties ha = left->properties(lambda), hb = right->properties(lambda);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_NEAR(a.sigma_a[i], ha.sigma_a[i], 1e-4f * ha.sigma_a[i]);
      EXPECT_NEAR(b.sigma_a[i], hb.sigma_a[i], 1e-4f * hb.sigma_a[i]);
      EXPECT_NEAR(mid.sigma_a[i], 0.5f * (ha.sigma_a[i] + hb.sigma_a[i]), 1e-4f * ha.sigma_a[i] + 1e-4f);
      EXPECT_FLOAT_EQ(a.sigma_s[i], 2.f);  // absent: 1, times scale
    }
  }
}

TEST(RGBGridMedium, MajorantsBoundSigmaTAlongRandomRays) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::string a, s;
  for (int i = 0; i < 4 * 3 * 5; ++i) {
    a += fmt::format(" {} {} {}", 2 * u(rng), u(rng), 0.1f * u(rng));
    s += fmt::format(" {} {} {}", u(rng) < 0.3f ? 0.f : 3 * u(rng), u(rng), 4 * u(rng) * u(rng));
  }
  const auto m = make("rgbgrid", "\"integer nx\" 4 \"integer ny\" 3 \"integer nz\" 5 \"rgb sigma_a\" [" + a +
                                     "] \"rgb sigma_s\" [" + s + "] \"float scale\" 1.5");
  int points = 0;
  for (int r = 0; r < 1000; ++r) {
    const SampledWavelengths lambda = SampledWavelengths::sample_uniform(u(rng));
    const Vec3 o = 4.f * glm::normalize(Vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f)) + Vec3(0.5f);
    const Ray ray{o, glm::normalize(Vec3(u(rng), u(rng), u(rng)) - o)};
    MajorantIterator it = m->majorants(ray, 20.f, lambda);
    while (auto seg = it.next())
      for (int k = 0; k < 4; ++k, ++points) {
        const MediumProperties mp = m->properties(ray.at(seg->t_min + u(rng) * (seg->t_max - seg->t_min)), lambda);
        for (int i = 0; i < kSpectrumSamples; ++i)
          EXPECT_LE(mp.sigma_a[i] + mp.sigma_s[i], seg->sigma_maj[i] * (1.f + 1e-5f) + 1e-6f);
      }
  }
  EXPECT_GT(points, 2000);
}

TEST(RGBGridMedium, EmissionIsTheRgbIlluminantTimesLescale) {
  const auto m = make("rgbgrid", "\"rgb sigma_a\" [1 1 1] \"rgb Le\" [0.5 0.5 0.5] \"float Lescale\" 3");
  EXPECT_TRUE(m->emissive());
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.3f);
  const MediumProperties mp = m->properties(Vec3(0.5f), lambda);
  // A grey RGB illuminant is the white itself: 0.5 * 3 * white, in pbrt-v4's film units.
  for (int i = 0; i < kSpectrumSamples; ++i)
    EXPECT_NEAR(mp.Le[i], 1.5f * cie_y_integral() * white_illuminant(lambda[i]), 2e-3f * mp.Le[i]);
  EXPECT_FALSE(make("rgbgrid", "\"rgb sigma_a\" [1 1 1]")->emissive());
}

TEST(RGBGridMedium, BadInputIsAnErrorNamingFileLineAndParameter) {
  auto error = [](const std::string& params) -> std::string {
    try {
      make("rgbgrid", params);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  for (auto [params, what] : {std::pair{"\"integer nx\" 2 \"rgb sigma_a\" [1 1 1]", "sigma_a"},
                              std::pair{"\"rgb sigma_s\" [1 -1 1]", "sigma_s"}, std::pair{"", "sigma_a"},
                              std::pair{"\"rgb sigma_s\" [1 1 1] \"rgb Le\" [1 1 1]", "Le"},
                              std::pair{"\"spectrum sigma_a\" [400 1 700 1]", "sigma_a"}}) {
    const std::string e = error(params);
    EXPECT_NE(e.find("r.pbrt:2"), std::string::npos) << e;
    EXPECT_NE(e.find(what), std::string::npos) << params << ": " << e;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
