// The "dielectric" material: exact Fresnel choice between specular reflection and
// refraction, Snell's law, radiance scaling, and its "eta" parameter forms.
#include <gtest/gtest.h>

#include "../support/spectral.h"
#include "../support/unity_id.h"

#include <random>

#include "core/arena.h"
#include "materials/dielectric_bxdf.h"
#include "materials/dielectric_material.h"
#include "materials/local_bsdf.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

SampledWavelengths g_lambda = test::wavelengths();

SurfaceInteraction hit() {
  SurfaceInteraction si;
  si.n = si.ns = Vec3(0.f, 0.f, 1.f);
  return si;
}

Param param(const std::string& type, const std::string& name, std::vector<double> numbers,
            std::vector<std::string> strings = {}) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"glass.pbrt", 4, 2};
  p.numbers = std::move(numbers);
  p.strings = std::move(strings);
  return p;
}

// The index the BSDF uses; `dispersed` tells whether the path kept only its hero wavelength.
float eta_of(const Material& m, bool* dispersed = nullptr) {
  ScratchBuffer arena;
  SampledWavelengths lambda = test::wavelengths();
  auto* b = dynamic_cast<const LocalBSDF<DielectricBxDF>*>(m.bsdf(hit(), lambda, arena));
  if (dispersed) *dispersed = lambda.secondary_terminated();
  EXPECT_NE(b, nullptr);
  return b ? b->bxdf().eta() : 0.f;
}

TEST(DielectricBxDF, ChoosesReflectionWithFresnelProbability) {
  DielectricBxDF d(1.5f, TrowbridgeReitz(0.f, 0.f));
  float theta = radians(50.f);
  Vec3 wo(std::sin(theta), 0.f, std::cos(theta));
  float f = fresnel_dielectric(wo.z, 1.5f);
  // uc below F reflects, above refracts; each with weight f cos / pdf exactly 1 (times
  // 1/eta^2 for radiance entering the denser medium).
  auto r = d.sample_f(wo, 0.999f * f, Vec2(0.5f));
  auto t = d.sample_f(wo, f + 0.001f * (1.f - f), Vec2(0.5f));
  ASSERT_TRUE(r && t);
  EXPECT_TRUE(r->flags & kReflection);
  EXPECT_TRUE(t->flags & kTransmission);
  EXPECT_NEAR(r->pdf, f, 1e-6f);
  EXPECT_NEAR(t->pdf, 1.f - f, 1e-6f);
  EXPECT_NEAR(r->f[0] * std::abs(r->wi.z) / r->pdf, 1.f, 1e-5f);
  EXPECT_NEAR(t->f[0] * std::abs(t->wi.z) / t->pdf, 1.f / (1.5f * 1.5f), 1e-5f);
  EXPECT_EQ(t->eta, 1.5f);
  // Mirror and Snell directions.
  EXPECT_NEAR(r->wi.x, -wo.x, 1e-6f);
  EXPECT_NEAR(r->wi.z, wo.z, 1e-6f);
  EXPECT_NEAR(-t->wi.x, std::sin(theta) / 1.5f, 1e-6f);
}

TEST(DielectricBxDF, TotalInternalReflectionFromInside) {
  DielectricBxDF d(1.5f, TrowbridgeReitz(0.f, 0.f));
  float theta = radians(50.f);  // beyond the critical angle 41.8 degrees
  Vec3 wo(std::sin(theta), 0.f, -std::cos(theta));
  for (float uc : {0.f, 0.5f, 0.999f}) {
    auto s = d.sample_f(wo, uc, Vec2(0.5f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->flags & kReflection);
    EXPECT_NEAR(s->pdf, 1.f, 1e-6f);
    EXPECT_LT(s->wi.z, 0.f);
  }
}

TEST(DielectricBxDF, EtaOneIsInvisible) {
  DielectricBxDF d(1.f, TrowbridgeReitz(0.f, 0.f));
  Vec3 wo = glm::normalize(Vec3(0.3f, 0.2f, 0.7f));
  auto s = d.sample_f(wo, 0.3f, Vec2(0.5f));
  ASSERT_TRUE(s);
  EXPECT_NEAR(glm::length(s->wi + wo), 0.f, 1e-6f);
  EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1.f, 1e-6f);
  EXPECT_EQ(d.flags(), unsigned(kTransmission | kSpecular));
}

TEST(DielectricBxDF, RoughTransmissionObeysGeneralisedReciprocity) {
  // Radiance transport across an index step: f(wi, wo) = eta^2 f(wo, wi) for wo outside and
  // wi inside (Veach 1997, section 5.2), while reflection stays symmetric.
  for (auto [eta, ax, ay] : {std::tuple{1.5f, 0.3f, 0.3f}, std::tuple{1.33f, 0.15f, 0.5f}}) {
    DielectricBxDF d(eta, TrowbridgeReitz(ax, ay));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u01(0.f, 1.f);
    int nonzero = 0;
    for (int i = 0; i < 4000; ++i) {
      Vec3 wo = sample_uniform_hemisphere(Vec2(u01(rng), u01(rng)));
      Vec3 wi = sample_uniform_hemisphere(Vec2(u01(rng), u01(rng)));
      wi.z = -wi.z;
      float a = d.f(wo, wi)[0], c = d.f(wi, wo)[0];
      EXPECT_NEAR(c, eta * eta * a, 1e-4f * std::max(1.f, c));
      nonzero += a > 0.f;
    }
    EXPECT_GT(nonzero, 50);
  }
}

TEST(DielectricMaterial, EtaForms) {
  TextureStore store;
  {
    ParameterList p;
    EXPECT_FLOAT_EQ(eta_of(*create_dielectric_material(MaterialContext{p, store, ""})), 1.5f);
  }
  {
    ParameterList p;
    p.add(param("float", "eta", {1.33}));
    bool dispersed = true;
    EXPECT_FLOAT_EQ(eta_of(*create_dielectric_material(MaterialContext{p, store, ""}), &dispersed), 1.33f);
    EXPECT_FALSE(dispersed);
  }
  {
    ParameterList p;
    p.add(param("spectrum", "eta", {}, {"glass-BK7"}));
    // The hero wavelength is about 494 nm: Schott gives n_F' = 1.52283 at 479.99 nm and
    // n_e = 1.51872 at 546.07 nm; the path keeps its hero wavelength only.
    bool dispersed = false;
    const float eta = eta_of(*create_dielectric_material(MaterialContext{p, store, ""}), &dispersed);
    const float l = test::wavelengths()[0];
    EXPECT_NEAR(eta, 1.52283f + (l - 479.99f) * (1.51872f - 1.52283f) / (546.07f - 479.99f), 5e-4f);
    EXPECT_TRUE(dispersed);
    EXPECT_TRUE(p.find("eta")->used);
  }
  {
    ParameterList p;
    p.add(param("spectrum", "eta", {400, 1.6, 700, 1.4}));
    const float l = test::wavelengths()[0];
    EXPECT_NEAR(eta_of(*create_dielectric_material(MaterialContext{p, store, ""})), 1.6f - 0.2f * (l - 400.f) / 300.f,
                1e-5f);
  }
}

TEST(DielectricMaterial, NonPositiveEtaIsAnError) {
  TextureStore store;
  ParameterList p;
  p.add(param("float", "eta", {0.0}));
  try {
    create_dielectric_material(MaterialContext{p, store, ""});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("glass.pbrt:4:2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"eta\""), std::string::npos) << e.what();
  }
}

TEST(DielectricMaterial, RoughnessIsRemapped) {
  // pbrt-v4: alpha = sqrt(roughness) unless remaproughness is false.
  TextureStore store;
  ParameterList p;
  p.add(param("float", "roughness", {0.01}));
  auto m = create_dielectric_material(MaterialContext{p, store, ""});
  ScratchBuffer arena;
  EXPECT_EQ(m->bsdf(hit(), g_lambda, arena)->flags() & kGlossy, unsigned(kGlossy));
  ParameterList q;
  q.add(param("float", "roughness", {0.0005}));
  Param b;
  b.type = "bool";
  b.name = "remaproughness";
  b.bools = {false};
  q.add(b);
  auto smooth = create_dielectric_material(MaterialContext{q, store, ""});
  EXPECT_EQ(smooth->bsdf(hit(), g_lambda, arena)->flags() & kSpecular, unsigned(kSpecular));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
