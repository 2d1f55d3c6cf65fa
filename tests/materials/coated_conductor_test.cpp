// The "coatedconductor" material's closed-form model (coated_conductor_bxdf.h): a coat of index 1
// without absorption is no coat (the metal's own BRDF and density, to float rounding); a nearly
// smooth metal under a smooth coat reflects F + T^2 R_c(mu') in all (the rough base's 1/n^2 and
// solid-angle compression checked by Monte Carlo against that single bounce); a smooth coat on a
// smooth metal reflects F + T^2 Rb (1 + F Rb + (F Rb)^2 + ...), summed here bounce by bounce,
// with Rb the metal's reflectance inside (index relative to the coat) times the round trip's
// absorption; through the renderer the pbrt-v4 parameter names of the collection's scenes are
// accepted and a smooth gold coat under a distant light gives that reflectance. Energy,
// sampling and reciprocity are in bsdf_properties_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/render_text.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"
#include "materials/coated_conductor_bxdf.h"
#include "materials/conductor_bxdf.h"
#include "materials/fresnel.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const SampledSpectrum kEta = test::channels(0.2f, 0.9f, 1.2f), kK = test::channels(3.3f, 2.6f, 2.3f);

TEST(CoatedConductor, AnIndexOneCoatIsNoCoat) {
  const TrowbridgeReitz rough(0.25f, 0.4f);
  const CoatedConductorBxDF coated(1.f, TrowbridgeReitz(0.f, 0.f), rough, kEta, kK, SampledSpectrum(0.f));
  const ConductorBxDF metal(rough, kEta, kK);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 300; ++i) {
    const Vec3 wo = sample_uniform_hemisphere(Vec2(u(rng), u(rng))),
               wi = sample_uniform_hemisphere(Vec2(u(rng), u(rng)));
    const SampledSpectrum a = coated.f(wo, wi), b = metal.f(wo, wi);
    // The refracted direction is recomputed (z from the tangential part): float rounding only.
    for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(a[c], b[c], 1e-3f * std::max(1.f, b[c]));
    EXPECT_NEAR(coated.pdf(wo, wi), metal.pdf(wo, wi), 1e-3f * std::max(1.f, metal.pdf(wo, wi)));
  }
}

TEST(CoatedConductor, SmoothLayersReflectTheSumOfTheBounces) {
  const float n = 1.5f;
  const SampledSpectrum tau = test::channels(0.f, 0.2f, 0.6f);
  const CoatedConductorBxDF b(n, TrowbridgeReitz(0.f, 0.f), TrowbridgeReitz(0.f, 0.f), kEta / n, kK / n, tau);
  for (float mu : {1.f, 0.7f, 0.3f, 0.05f}) {
    const float f = fresnel_dielectric(mu, n), t = 1.f - f;
    const float mu_in = std::sqrt(1.f - (1.f - mu * mu) / (n * n));
    const SampledSpectrum rc = fresnel_complex(mu_in, kEta / n, kK / n);
    const Vec3 wo(std::sqrt(1.f - mu * mu), 0.f, mu);
    auto s = b.sample_f(wo, 0.5f, Vec2(0.5f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_specular());
    for (int c = 0; c < kSpectrumSamples; ++c) {
      const double rb = double(rc[c]) * std::exp(-2.0 * tau[c] / mu_in);
      double sum = f, bounce = double(t) * rb * t;  // in, metal, out
      for (int j = 0; j < 10000 && bounce > 1e-15; ++j, bounce *= double(f) * rb) sum += bounce;
      EXPECT_NEAR(s->f[c] * mu / s->pdf, sum, 1e-5) << "mu " << mu << " channel " << c;
    }
  }
}

TEST(CoatedConductor, ANearlySmoothMetalUnderASmoothCoatReflectsTheSingleBounce) {
  const float n = 1.5f;
  // alpha 0.005: rough for the code (its lobe is sampled and evaluated), nearly a mirror. Angles
  // whose refracted mirror direction is well inside the coat's critical cone (at mu = 0.3 it is
  // 2 degrees from it, and the model loses what the lobe sends beyond: see the header).
  const CoatedConductorBxDF b(n, TrowbridgeReitz(0.f, 0.f), TrowbridgeReitz(0.005f, 0.005f), kEta / n, kK / n,
                              SampledSpectrum(0.f));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, kOneMinusEpsilon);
  for (float mu : {0.95f, 0.8f, 0.6f}) {
    const Vec3 wo(std::sqrt(1.f - mu * mu), 0.f, mu);
    const int count = 200000;
    SampledSpectrum sum(0.f);
    for (int i = 0; i < count; ++i) {
      auto s = b.sample_f(wo, u(rng), Vec2(u(rng), u(rng)));
      if (s) sum += s->f * std::abs(s->wi.z) / s->pdf;
    }
    const float f = fresnel_dielectric(mu, n), t = 1.f - f;
    const SampledSpectrum rc = fresnel_complex(std::sqrt(1.f - (1.f - mu * mu) / (n * n)), kEta / n, kK / n);
    for (int c = 0; c < kSpectrumSamples; ++c)
      EXPECT_NEAR(sum[c] / count, f + t * t * rc[c], 0.01) << "mu " << mu << " channel " << c;
  }
}

// The mean of a square seen from straight above, lit by a distant light from straight above
// (the camera and light near the normal: the reflected direction is the camera's).
double lit(const std::string& material) {
  const std::string text = fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 1
    Film "rgb" "integer xresolution" 4 "integer yresolution" 4
    Sampler "independent" "integer pixelsamples" 4
    Integrator "path" "integer maxdepth" 2
    WorldBegin
    AttributeBegin
      Material "diffuse" "rgb reflectance" [0 0 0]
      AreaLightSource "diffuse" "rgb L" [1 1 1]
      Shape "trianglemesh" "integer indices" [0 2 1 0 3 2] "point3 P" [-100 -100 6  100 -100 6  100 100 6  -100 100 6]
    AttributeEnd
    Material {}
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
  )",
                                       material);
  return test::channel_mean(test::render_text(text, "cc.pbrt"), 1);  // green
}

TEST(CoatedConductor, PbrtV4ParametersRenderAndAMirrorMetalUnderAnIndexOneCoatIsTheMetal) {
  // The camera sees the emitter (radiance 1) mirrored: the image is the reflectance at normal
  // incidence. An index-1 coat over a smooth metal of normal reflectance 0.6: 0.6.
  const double metal = lit(R"("conductor" "rgb reflectance" [0.6 0.6 0.6])");
  EXPECT_NEAR(metal, 0.6, 0.01);
  EXPECT_NEAR(lit(R"("coatedconductor" "float interface.eta" 1 "float thickness" 0 "rgb reflectance" [0.6 0.6 0.6])"),
              metal, 1e-4);
  // The collection's spelling (killeroo-coated-gold) is accepted and reflects less than bare gold
  // at normal incidence through a 1.5 coat of no absorption but more than the coat alone (0.04).
  const double gold = lit(R"("coatedconductor" "float interface.roughness" 0 "spectrum conductor.eta" "metal-Au-eta"
      "spectrum conductor.k" "metal-Au-k" "float conductor.roughness" 0 "float thickness" 0)");
  const double bare = lit(R"("conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k")");
  EXPECT_GT(gold, 0.04);
  EXPECT_LT(gold, bare);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
