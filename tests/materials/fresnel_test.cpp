// Fresnel reflectance and refraction (materials/fresnel.h) against closed forms.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "materials/fresnel.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(FresnelDielectric, NormalIncidence) {
  for (float n : {1.33f, 1.5f, 2.4f}) EXPECT_NEAR(fresnel_dielectric(1.f, n), sqr((n - 1.f) / (n + 1.f)), 1e-6f) << n;
  EXPECT_EQ(fresnel_dielectric(1.f, 1.f), 0.f);
}

TEST(FresnelDielectric, BrewsterAngleReflectsHalfTheSPolarisation) {
  // At tan(theta_B) = n the p reflectance vanishes and r_s = (1 - n^2) / (1 + n^2).
  for (float n : {1.33f, 1.5f, 1.9f}) {
    float cos_b = 1.f / std::sqrt(1.f + n * n);
    float rs = sqr((1.f - n * n) / (1.f + n * n));
    EXPECT_NEAR(fresnel_dielectric(cos_b, n), 0.5f * rs, 1e-6f) << n;
  }
}

TEST(FresnelDielectric, MatchesTheTwoPolarisationFormulas) {
  // Snell + Fresnel equations written out in angles, for light from outside.
  float n = 1.5f;
  for (float deg : {10.f, 40.f, 70.f, 85.f}) {
    float ti = radians(deg), tt = std::asin(std::sin(ti) / n);
    float rs = sqr(std::sin(ti - tt) / std::sin(ti + tt));
    float rp = sqr(std::tan(ti - tt) / std::tan(ti + tt));
    EXPECT_NEAR(fresnel_dielectric(std::cos(ti), n), 0.5f * (rs + rp), 2e-6f) << deg;
  }
}

TEST(FresnelDielectric, TotalInternalReflectionBeyondCriticalAngle) {
  float n = 1.5f, critical = std::asin(1.f / n);
  EXPECT_EQ(fresnel_dielectric(-std::cos(critical + 0.01f), n), 1.f);
  EXPECT_EQ(fresnel_dielectric(-std::cos(radians(80.f)), n), 1.f);
  EXPECT_LT(fresnel_dielectric(-std::cos(critical - 0.01f), n), 1.f);
  // Inside at normal incidence: the same reflectance as outside.
  EXPECT_NEAR(fresnel_dielectric(-1.f, n), fresnel_dielectric(1.f, n), 1e-7f);
}

TEST(FresnelComplex, NormalIncidenceOfConductor) {
  for (auto [n, k] : {std::pair{0.2f, 3.9f}, std::pair{1.1f, 2.6f}, std::pair{0.05f, 4.2f}})
    EXPECT_NEAR(fresnel_complex(1.f, n, k), (sqr(n - 1.f) + k * k) / (sqr(n + 1.f) + k * k), 1e-5f) << n << " " << k;
}

TEST(FresnelComplex, ZeroAbsorptionIsTheDielectric) {
  for (float c : {1.f, 0.7f, 0.3f, 0.05f})
    EXPECT_NEAR(fresnel_complex(c, 1.5f, 0.f), fresnel_dielectric(c, 1.5f), 1e-5f);
}

TEST(FresnelComplex, GrazingIncidenceReflectsEverything) { EXPECT_NEAR(fresnel_complex(0.f, 0.2f, 3.9f), 1.f, 1e-6f); }

TEST(Refract, SnellsLaw) {
  float n = 1.5f, etap = 0.f;
  Vec3 wi = glm::normalize(Vec3(0.6f, 0.f, 0.8f)), wt;
  ASSERT_TRUE(refract(wi, Vec3(0.f, 0.f, 1.f), n, &etap, &wt));
  EXPECT_EQ(etap, n);
  EXPECT_NEAR(glm::length(wt), 1.f, 1e-6f);
  float sin_i = std::sqrt(1.f - wi.z * wi.z), sin_t = std::sqrt(1.f - wt.z * wt.z);
  EXPECT_NEAR(sin_i, n * sin_t, 1e-6f);
  EXPECT_LT(wt.z, 0.f);
  EXPECT_LT(wt.x, 0.f);  // continues across the normal
  // Back out through the surface, beyond the critical angle: no refraction.
  Vec3 inside = glm::normalize(Vec3(0.9f, 0.f, -0.3f));
  EXPECT_FALSE(refract(inside, Vec3(0.f, 0.f, 1.f), n, &etap, &wt));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
