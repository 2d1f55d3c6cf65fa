// The closed-form coated-diffuse model: exact limits (no coat = Lambertian; white base
// without absorption reflects everything) and its parameters.
#include <gtest/gtest.h>

#include "../support/params.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include <random>

#include "core/arena.h"
#include "materials/coated_diffuse_bxdf.h"
#include "materials/coated_diffuse_material.h"
#include "materials/local_bsdf.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

SurfaceInteraction hit() {
  SurfaceInteraction si;
  si.n = si.ns = Vec3(0.f, 0.f, 1.f);
  return si;
}

constexpr auto number = test::number_param;

// Mean of f cos / pdf over n samples, and its standard error.
std::pair<SampledSpectrum, SampledSpectrum> albedo(const BSDF& b, const Vec3& wo, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.f, kOneMinusEpsilon);
  SampledSpectrum sum(0.f), sum2(0.f);
  for (int i = 0; i < n; ++i) {
    auto s = b.sample_f(wo, u01(rng), Vec2(u01(rng), u01(rng)));
    if (!s) continue;
    SampledSpectrum w = s->f * std::abs(s->wi.z) / s->pdf;
    sum += w;
    sum2 += w * w;
  }
  SampledSpectrum mean = sum / float(n);
  return {mean, sqrt(test::max0(sum2 / float(n) - mean * mean) / float(n))};
}

TEST(CoatedDiffuseBxDF, WithoutCoatItIsLambertian) {
  CoatedDiffuseBxDF b(CoatConstants::make(1.f), TrowbridgeReitz(0.f, 0.f), test::channels(0.3f, 0.6f, 0.9f),
                      SampledSpectrum(0.f));
  Vec3 wo = glm::normalize(Vec3(0.4f, 0.1f, 0.6f)), wi = glm::normalize(Vec3(-0.2f, 0.5f, 0.3f));
  SampledSpectrum f = b.f(wo, wi);
  EXPECT_NEAR(f[0], 0.3f / kPi, 1e-4f);
  EXPECT_NEAR(f[1], 0.6f / kPi, 1e-4f);
  EXPECT_NEAR(f[2], 0.9f / kPi, 1e-4f);
}

TEST(CoatedDiffuseBxDF, MeanCoatTransmittanceIsOneMinusDiffuseFresnel) {
  // Independent computation: the angle form of the Fresnel equations (Snell's law, r_s and
  // r_p as sin/tan ratios) integrated over theta with Simpson's rule. The result, 0.0918
  // for n = 1.5, gives the textbook internal diffuse reflectance 1 - 0.908 / 1.5^2 = 0.596.
  for (double n : {1.33, 1.5, 2.0}) {
    const int m = 2000;
    double sum = 0.0, h = (kPi / 2.0) / m;
    for (int i = 0; i <= m; ++i) {
      double ti = std::max(1e-9, i * h), tt = std::asin(std::sin(ti) / n);
      double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2.0);
      double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2.0);
      double w = (i == 0 || i == m) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += w * 0.5 * (rs + rp) * 2.0 * std::cos(ti) * std::sin(ti);  // 2 mu dmu = 2 cos sin dtheta
    }
    double f_mean = sum * h / 3.0;
    if (n == 1.5) EXPECT_NEAR(f_mean, 0.0918, 1e-4);
    EXPECT_NEAR(CoatConstants::make(float(n)).t_mean, 1.0 - f_mean, 2e-4) << n;
  }
}

TEST(CoatedDiffuseBxDF, WhiteNonAbsorbingLayerReflectsAllLight) {
  // With R = 1, no absorption and a smooth coat, the model's albedo is F + (1 - F) = 1 for
  // every direction: energy is conserved exactly, not merely bounded.
  ScratchBuffer arena;
  const BSDF* b = make_local_bsdf(arena, hit(),
                                  CoatedDiffuseBxDF(CoatConstants::make(1.5f), TrowbridgeReitz(0.f, 0.f),
                                                    SampledSpectrum(1.f), SampledSpectrum(0.f)));
  for (float theta : {0.f, 45.f, 75.f, 89.f}) {
    Vec3 wo(std::sin(radians(theta)), 0.f, std::cos(radians(theta)));
    auto [mean, se] = albedo(*b, wo, 200000, 17);
    EXPECT_NEAR(mean[1], 1.f, 4.f * se[1] + 1e-4f) << theta;
  }
}

TEST(CoatedDiffuseBxDF, AbsorbingLayerIsDarker) {
  ScratchBuffer arena;
  SurfaceInteraction si = hit();
  auto coat = CoatConstants::make(1.5f);
  const BSDF* clear = make_local_bsdf(
      arena, si, CoatedDiffuseBxDF(coat, TrowbridgeReitz(0.f, 0.f), SampledSpectrum(0.8f), SampledSpectrum(0.f)));
  const BSDF* tinted = make_local_bsdf(
      arena, si,
      CoatedDiffuseBxDF(coat, TrowbridgeReitz(0.f, 0.f), SampledSpectrum(0.8f), test::channels(0.f, 0.f, 0.5f)));
  Vec3 wo(0.f, 0.f, 1.f), wi = glm::normalize(Vec3(0.3f, 0.f, 1.f));
  EXPECT_NEAR(tinted->f(wo, wi)[0], clear->f(wo, wi)[0], 1e-7f);
  EXPECT_LT(tinted->f(wo, wi)[2], 0.5f * clear->f(wo, wi)[2]);
}

TEST(CoatedDiffuseMaterial, ReadsEveryPbrtV4Parameter) {
  ParameterList p;
  p.add(number("rgb", "reflectance", {0.2, 0.4, 0.6}));
  p.add(number("float", "roughness", {0.1}));
  p.add(number("float", "thickness", {0.02}));
  p.add(number("float", "eta", {1.4}));
  p.add(number("rgb", "albedo", {0.5, 0.5, 0.5}));
  p.add(number("float", "g", {0.3}));
  p.add(number("integer", "maxdepth", {5}));
  p.add(number("integer", "nsamples", {2}));
  TextureStore store;
  auto m = create_coateddiffuse_material(MaterialContext{p, store, ""});
  for (const auto& param : p.params()) EXPECT_TRUE(param.used) << param.name;
  ScratchBuffer arena;
  SampledWavelengths lambda = test::wavelengths();
  const BSDF* b = m->bsdf(hit(), lambda, arena);
  EXPECT_EQ(b->flags(), unsigned(kReflection | kDiffuse | kGlossy));
  EXPECT_TRUE(is_finite(b->f(Vec3(0, 0, 1), glm::normalize(Vec3(0.3f, 0, 1)))));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
