// The "mix" material (pbrt-v4's MixMaterial): one of two named materials per hit, the second
// with probability `amount`, chosen by a hash of the point and direction. Checked: the hash is
// uniform (a binomial test at 4 sigma) and repeatable; amounts 0 and 1 pick one material
// exactly; through the renderer a 25 % mix of reflectances 0.2 and 0.8 on a lit plane has the
// mean of reflectance 0.35 within 4 sigma of the choice's binomial noise; the scene errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/render_text.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"
#include "core/arena.h"
#include "core/error.h"
#include "materials/diffuse_material.h"
#include "materials/mix_material.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(MixMaterial, HashIsUniformAndRepeatable) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-10.f, 10.f);
  const int n = 200000;
  int below[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng)), wo = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const float h = mix_material_hash(p, wo, 7);
    ASSERT_TRUE(h >= 0.f && h < 1.f);
    ASSERT_EQ(h, mix_material_hash(p, wo, 7));
    for (int q = 0; q < 4; ++q) below[q] += h < 0.2f * float(q + 1);
  }
  for (int q = 0; q < 4; ++q) {
    const double pq = 0.2 * (q + 1), sigma = std::sqrt(n * pq * (1 - pq));
    EXPECT_NEAR(below[q], n * pq, 4 * sigma) << "P(h < " << pq << ")";
  }
  // Neighbouring points (one float step apart) are not correlated: the same binomial test.
  int low = 0;
  for (int i = 0; i < n; ++i) low += mix_material_hash(Vec3(1.f + float(i) * 1e-6f, 2.f, 3.f), Vec3(0, 0, 1), 7) < 0.5f;
  EXPECT_NEAR(low, n / 2, 4 * std::sqrt(n * 0.25));
}

// The image mean of a square seen from +z under a distant light at 45 degrees, with material
// text `material` (after two named diffuse materials "dark" 0.2 and "light" 0.8).
double lit_plane(const std::string& material, int spp) {
  const std::string text = fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 8
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "independent" "integer pixelsamples" {}
    Integrator "path" "integer maxdepth" 1
    WorldBegin
    LightSource "distant" "point3 from" [-1 0 1] "point3 to" [0 0 0] "rgb L" [1 1 1]
    MakeNamedMaterial "dark" "string type" "diffuse" "rgb reflectance" [0.2 0.2 0.2]
    MakeNamedMaterial "light" "string type" "diffuse" "rgb reflectance" [0.8 0.8 0.8]
    {}
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
  )",
                                       spp, material);
  return test::image_mean(test::render_text(text, "mix.pbrt"));
}

TEST(MixMaterial, AmountsZeroAndOneAreTheMaterialsAndAQuarterIsTheBlend) {
  const double dark = lit_plane(R"(NamedMaterial "dark")", 1), light = lit_plane(R"(NamedMaterial "light")", 1);
  ASSERT_NEAR(light / dark, 4.0, 1e-4);
  EXPECT_NEAR(lit_plane(R"(Material "mix" "string materials" ["dark" "light"] "float amount" 0)", 1), dark, 1e-6);
  EXPECT_NEAR(lit_plane(R"(Material "mix" "string materials" ["dark" "light"] "float amount" 1)", 1), light, 1e-6);
  // 16 x 16 pixels x 64 samples, each a Bernoulli(0.25) choice between the two values.
  const int n = 16 * 16 * 64;
  const double mixed = lit_plane(R"(Material "mix" "string materials" ["dark" "light"] "float amount" 0.25)", 64);
  const double expected = 0.75 * dark + 0.25 * light, sigma = (light - dark) * std::sqrt(0.25 * 0.75 / n);
  EXPECT_NEAR(mixed, expected, 4 * sigma);
  // A mix can name a mix, and "interface" (the ray passes, nothing behind: black). Outer: light
  // or the inner mix, half each; inner: dark or nothing, half each. Means 0.5 light + 0.25 dark;
  // were the two choices one hash (tied), the inner would never pick dark: 0.5 light.
  const double nested = lit_plane(R"(MakeNamedMaterial "none" "string type" "interface"
      MakeNamedMaterial "inner" "string type" "mix" "string materials" ["dark" "none"] "float amount" 0.5
      Material "mix" "string materials" ["inner" "light"] "float amount" 0.5)",
                                  64);
  const double mean = 0.5 * light + 0.25 * dark, second = 0.5 * light * light + 0.25 * dark * dark;
  EXPECT_NEAR(nested, mean, 4 * std::sqrt((second - mean * mean) / n));
}

std::string error_of(const std::string& material) {
  try {
    lit_plane(material, 1);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(MixMaterial, BadReferencesAreErrors) {
  EXPECT_NE(error_of(R"(MakeNamedMaterial "loop" "string type" "mix" "string materials" ["dark" "loop"]
                        NamedMaterial "loop")")
                .find("contains itself"),
            std::string::npos);
  EXPECT_NE(error_of(R"(Material "mix" "string materials" ["dark" "nowhere"])").find("\"nowhere\" is not defined"),
            std::string::npos);
  EXPECT_NE(error_of(R"(Material "mix" "string materials" ["dark"])").find("takes 2 values"), std::string::npos);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
