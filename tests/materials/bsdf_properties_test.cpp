// Properties every BSDF must have, checked for each BxDF in several configurations:
//  - energy conservation: the Monte Carlo directional albedo is <= 1 (one-sided test at
//    4 standard errors, false-alarm probability 3e-5 per direction);
//  - sample_f agrees with f() and pdf() for non-specular samples;
//  - the sampled directions follow pdf() (Pearson chi-square, significance 1e-4 per test);
//  - reciprocity f(wo, wi) = f(wi, wo) for reflection (transmission: dielectric_test.cpp), for
//    the BxDFs that are reciprocal (not Chiang et al.'s hair model: its azimuthal lobes depend
//    on wo's angles only).
#include <gtest/gtest.h>

#include "../support/spectral.h"
#include "../support/unity_id.h"

#include <functional>
#include <random>

#include "../support/chi2.h"
#include "../support/sample_count.h"
#include "core/arena.h"
#include "materials/coated_conductor_bxdf.h"
#include "materials/coated_diffuse_bxdf.h"
#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "materials/diffuse_transmission_bxdf.h"
#include "materials/hair_bxdf.h"
#include "materials/lambertian_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/thin_dielectric_bxdf.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct Case {
  std::string name;
  std::function<const BSDF*(ScratchBuffer&, const SurfaceInteraction&)> make;
  bool all_specular = false;
  bool reciprocal = true;
};

SurfaceInteraction flat_hit() {
  SurfaceInteraction si;
  si.n = si.ns = Vec3(0.f, 0.f, 1.f);
  si.dpdu = Vec3(1.f, 0.f, 0.f);
  si.dpdv = Vec3(0.f, 1.f, 0.f);
  return si;
}

const SampledSpectrum kCuEta = test::channels(0.104f, 0.978f, 1.205f), kCuK = test::channels(3.273f, 2.592f, 2.369f);

std::vector<Case> cases() {
  auto mf = [](float ax, float ay) { return TrowbridgeReitz(ax, ay); };
  auto coat = [](float eta) { return CoatConstants::make(eta); };
  return {
      {"lambertian",
       [](auto& a, auto& si) { return make_local_bsdf(a, si, LambertianBxDF(test::channels(1.f, 0.8f, 0.3f))); }},
      {"diffuse_transmission",
       [](auto& a, auto& si) {
         return make_local_bsdf(
             a, si, DiffuseTransmissionBxDF(test::channels(0.2f, 0.5f, 0.1f), test::channels(0.7f, 0.3f, 0.05f)));
       }},
      {"diffuse_transmission_only",
       [](auto& a, auto& si) {
         return make_local_bsdf(a, si, DiffuseTransmissionBxDF(SampledSpectrum(0.f), SampledSpectrum(1.f)));
       }},
      {"dielectric_smooth",
       [=](auto& a, auto& si) { return make_local_bsdf(a, si, DielectricBxDF(1.5f, mf(0.f, 0.f))); }, true},
      {"dielectric_rough",
       [=](auto& a, auto& si) { return make_local_bsdf(a, si, DielectricBxDF(1.5f, mf(0.3f, 0.3f))); }},
      {"dielectric_aniso",
       [=](auto& a, auto& si) { return make_local_bsdf(a, si, DielectricBxDF(1.33f, mf(0.15f, 0.5f))); }},
      {"thin_dielectric", [](auto& a, auto& si) { return make_local_bsdf(a, si, ThinDielectricBxDF(1.5f)); }, true},
      {"conductor_smooth",
       [=](auto& a, auto& si) { return make_local_bsdf(a, si, ConductorBxDF(mf(0.f, 0.f), kCuEta, kCuK)); }, true},
      {"conductor_rough",
       [=](auto& a, auto& si) { return make_local_bsdf(a, si, ConductorBxDF(mf(0.3f, 0.3f), kCuEta, kCuK)); }},
      {"conductor_aniso",
       [=](auto& a, auto& si) {
         return make_local_bsdf(a, si, ConductorBxDF(mf(0.1f, 0.4f), SampledSpectrum(1.f), SampledSpectrum(8.f)));
       }},
      {"coatedconductor_smooth_smooth",
       [=](auto& a, auto& si) {
         return make_local_bsdf(
             a, si,
             CoatedConductorBxDF(1.5f, mf(0.f, 0.f), mf(0.f, 0.f), kCuEta / 1.5f, kCuK / 1.5f, SampledSpectrum(0.f)));
       },
       true},
      {"coatedconductor_smooth_coat_rough_metal",
       [=](auto& a, auto& si) {
         return make_local_bsdf(
             a, si,
             CoatedConductorBxDF(1.5f, mf(0.f, 0.f), mf(0.3f, 0.3f), kCuEta / 1.5f, kCuK / 1.5f, SampledSpectrum(0.f)));
       }},
      {"coatedconductor_rough_coat_smooth_metal",
       [=](auto& a, auto& si) {
         return make_local_bsdf(a, si,
                                CoatedConductorBxDF(1.5f, mf(0.2f, 0.2f), mf(0.f, 0.f), kCuEta / 1.5f, kCuK / 1.5f,
                                                    SampledSpectrum(3.f)));  // absorbing: mostly the glossy coat
       }},
      {"coatedconductor_rough_aniso_absorbing",
       [=](auto& a, auto& si) {
         return make_local_bsdf(a, si,
                                CoatedConductorBxDF(1.8f, mf(0.3f, 0.3f), mf(0.1f, 0.4f), SampledSpectrum(0.2f),
                                                    SampledSpectrum(3.f), test::channels(0.5f, 0.1f, 0.f)));
       }},
      {"coated_smooth_white",
       [=](auto& a, auto& si) {
         return make_local_bsdf(
             a, si, CoatedDiffuseBxDF(coat(1.5f), mf(0.f, 0.f), SampledSpectrum(1.f), SampledSpectrum(0.f)));
       }},
      {"coated_rough_white",
       [=](auto& a, auto& si) {
         return make_local_bsdf(
             a, si, CoatedDiffuseBxDF(coat(1.5f), mf(0.3f, 0.3f), SampledSpectrum(1.f), SampledSpectrum(0.f)));
       }},
      {"coated_rough_dense",
       [=](auto& a, auto& si) {
         return make_local_bsdf(
             a, si,
             CoatedDiffuseBxDF(coat(2.4f), mf(0.6f, 0.6f), test::channels(0.9f, 0.5f, 0.1f), SampledSpectrum(0.2f)));
       }},
      // Hair: the fibre along x (dpdu), h across it. White; absorbing near the edge, rougher.
      {"hair_white",
       [](auto& a, auto& si) {
         return make_local_bsdf(a, si, HairBxDF(0.3f, 1.55f, SampledSpectrum(0.f), 0.3f, 0.3f, 2.f));
       },
       false, false},
      {"hair_brown_edge",
       [](auto& a, auto& si) {
         return make_local_bsdf(a, si, HairBxDF(-0.9f, 1.55f, test::channels(0.54f, 0.91f, 1.78f), 0.5f, 0.4f, 3.f));
       },
       false, false},
  };
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

Vec3 direction(float theta_deg, float phi, bool below = false) {
  float t = radians(theta_deg);
  Vec3 w(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
  if (below) w.z = -w.z;
  return w;
}

Vec3 from_cos_phi(double cos_t, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  return Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(cos_t));
}

class BsdfProperties : public ::testing::TestWithParam<Case> {
 protected:
  ScratchBuffer arena_;
  SurfaceInteraction si_ = flat_hit();
  const BSDF* bsdf() { return GetParam().make(arena_, si_); }
};

TEST_P(BsdfProperties, DirectionalAlbedoIsAtMostOne) {
  const BSDF* b = bsdf();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u01(0.f, kOneMinusEpsilon);
  const int n = test::sample_count(100000);
  for (bool below : {false, true})
    for (float theta : {0.f, 30.f, 60.f, 80.f, 88.f}) {
      Vec3 wo = direction(theta, 0.7f, below);
      SampledSpectrum sum(0.f), sum2(0.f);
      for (int i = 0; i < n; ++i) {
        auto s = b->sample_f(wo, u01(rng), Vec2(u01(rng), u01(rng)));
        if (!s) continue;
        SampledSpectrum w = s->f * std::abs(s->wi.z) / s->pdf;
        if (s->flags & kTransmission) w *= sqr(s->eta);  // energy, not radiance
        sum += w;
        sum2 += w * w;
      }
      SampledSpectrum mean = sum / float(n);
      SampledSpectrum se = sqrt(test::max0(sum2 / float(n) - mean * mean) / float(n));
      for (int c = 0; c < kSpectrumSamples; ++c)
        EXPECT_LE(mean[c], 1.f + 4.f * se[c] + 1e-4f) << GetParam().name << " theta " << theta << " below " << below;
    }
}

TEST_P(BsdfProperties, SamplesAgreeWithEvaluation) {
  const BSDF* b = bsdf();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u01(0.f, kOneMinusEpsilon);
  int checked = 0;
  for (float theta : {20.f, 70.f})
    for (int i = 0; i < 2000; ++i) {
      Vec3 wo = direction(theta, 1.3f, i % 2 == 1);
      auto s = b->sample_f(wo, u01(rng), Vec2(u01(rng), u01(rng)));
      if (!s) continue;
      EXPECT_TRUE(is_finite(s->f));
      EXPECT_GT(s->pdf, 0.f);
      if (s->is_specular()) {
        if (GetParam().all_specular) EXPECT_EQ(b->pdf(wo, s->wi), 0.f) << "specular directions have no density";
        continue;
      }
      SampledSpectrum f = b->f(wo, s->wi);
      float pdf = b->pdf(wo, s->wi);
      for (int c = 0; c < kSpectrumSamples; ++c)
        EXPECT_NEAR(s->f[c], f[c], 1e-3f * std::max(1.f, f[c])) << GetParam().name;
      EXPECT_NEAR(s->pdf, pdf, 1e-3f * std::max(1.f, pdf)) << GetParam().name;
      ++checked;
    }
  if (!GetParam().all_specular) EXPECT_GT(checked, 1000);
}

TEST_P(BsdfProperties, SampledDirectionsFollowPdf) {
  if (GetParam().all_specular) GTEST_SKIP() << "only specular lobes";
  const BSDF* b = bsdf();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u01(0.f, kOneMinusEpsilon);
  const int n = test::sample_count(200000);
  for (float theta : {25.f, 65.f}) {
    Vec3 wo = direction(theta, 0.4f);
    // Cells in (cos theta, phi): solid angle is dcos dphi, so the density is pdf() itself.
    chi2::Grid2D grid(20, 40, -1.0, 1.0, 0.0, 2.0 * kPi);
    int other = 0;  // specular or failed samples
    for (int i = 0; i < n; ++i) {
      auto s = b->sample_f(wo, u01(rng), Vec2(u01(rng), u01(rng)));
      if (!s || s->is_specular()) {
        ++other;
        continue;
      }
      double phi = std::atan2(s->wi.y, s->wi.x);
      if (phi < 0.0) phi += 2.0 * kPi;
      grid.add(std::clamp(double(s->wi.z), -1.0, 1.0), phi);
    }
    auto density = [&](double c, double phi) { return double(b->pdf(wo, from_cos_phi(c, phi))); };
    std::vector<double> expected = chi2::expected_per_cell(grid, density, n, test::kChi2Panels);
    std::vector<double> observed = grid.counts;
    double in_grid = 0.0;
    for (double e : expected) in_grid += e;
    observed.push_back(other + double(grid.outside));
    expected.push_back(std::max(0.0, n - in_grid));
    chi2::Result r = chi2::pearson(observed, expected);
    EXPECT_TRUE(r.passes(1e-4)) << GetParam().name << " theta " << theta << ": " << r.summary();
    RecordProperty("chi2_theta" + std::to_string(int(theta)), r.summary());
  }
}

TEST_P(BsdfProperties, ReflectionIsReciprocal) {
  if (!GetParam().reciprocal) GTEST_SKIP() << "not a reciprocal model";
  const BSDF* b = bsdf();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  for (int i = 0; i < 500; ++i) {
    Vec3 wo = sample_uniform_hemisphere(Vec2(u01(rng), u01(rng)));
    Vec3 wi = sample_uniform_hemisphere(Vec2(u01(rng), u01(rng)));
    SampledSpectrum a = b->f(wo, wi), c = b->f(wi, wo);
    for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(a[k], c[k], 1e-4f * std::max(1.f, a[k])) << GetParam().name;
  }
}

INSTANTIATE_TEST_SUITE_P(AllBxDFs, BsdfProperties, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
