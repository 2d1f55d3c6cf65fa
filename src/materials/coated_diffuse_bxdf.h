// A Lambertian base under a dielectric coat (pbrt-v4's "coateddiffuse"), as a closed-form
// two-lobe model instead of pbrt-v4's stochastic layered random walk:
//
//   f = f_coat + f_base
//   f_coat = specular reflection with F(mu_o), or for a rough coat the Trowbridge-Reitz lobe
//            D G min(F(mu_o), F(mu_i)) / (4 mu_o mu_i)
//   f_base = R T(mu_o) T(mu_i) A(mu_o') A(mu_i') / (pi K),   T = 1 - F,
//            K = n^2 (1 - R Abar^2) + R Abar^2 Tbar
//
// with F the dielectric Fresnel reflectance at the macro-surface angle, Tbar the cosine-
// weighted hemispherical mean of T, A(mu') = exp(-tau / mu') the absorption along the
// refracted direction inside the coat (tau = thickness (1 - albedo)) and Abar^2 = exp(-4 tau)
// that of a diffuse round trip. K is the multiple-bounce sum between base and coat
// (Kelemen & Szirmay-Kalos 2001, Weidlich & Wilkie 2007): 1 - Tbar/n^2 of the diffuse light
// inside is reflected back by the coat.
//
// Energy conservation, for every mu_o (with n >= 1, R <= 1):
//   albedo_coat <= F(mu_o)   (the Fresnel factor is at most F(mu_o), and the microfacet lobe
//                             without Fresnel has albedo G2/G1-weighted <= 1)
//   albedo_base <= T(mu_o) R Tbar / K <= T(mu_o) = 1 - F(mu_o)
//                            (K - R Tbar >= n^2 (1 - R) >= 0 since Tbar <= 1 <= n^2)
// so the sum is <= 1. Both lobes are symmetric in (mu_o, mu_i): reciprocal.
//
// Differences from pbrt-v4: the coat Fresnel is taken at the macro angles, not per
// microfacet; light scattered inside the coat ("albedo", "g") only reduces absorption and
// adds no volumetric scattering lobe; "maxdepth" and "nsamples" have no meaning (the model
// is deterministic). Like pbrt-v4's it is two-sided.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "core/sampling.h"
#include "materials/bxdf_util.h"
#include "materials/fresnel.h"
#include "materials/microfacet.h"

namespace eyetrace {

// Parts of the model that depend only on the coat's index: computed once per material.
struct CoatConstants {
  float eta = 1.5f;
  float n2 = 2.25f;    // max(eta^2, 1): keeps K >= R Tbar for coats thinner than outside
  float t_mean = 1.f;  // Tbar, rounded up
  static CoatConstants make(float eta);
};

class CoatedDiffuseBxDF {
 public:
  // tau: optical thickness of the coat per channel (thickness x absorbed fraction).
  CoatedDiffuseBxDF(const CoatConstants& c, const TrowbridgeReitz& mf, const SampledSpectrum& reflectance,
                    const SampledSpectrum& tau);

  unsigned flags() const { return kReflection | kDiffuse | (mf_.effectively_smooth() ? kSpecular : kGlossy); }
  SampledSpectrum albedo() const;

  SampledSpectrum f(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  std::optional<BSDFSample> sample_f(Vec3 wo, float uc, Vec2 u) const;

 private:
  float fresnel(float mu) const { return fresnel_dielectric(std::abs(mu), c_.eta); }
  SampledSpectrum base(float mu_o, float mu_i) const;
  float coat_f(const Vec3& wo, const Vec3& wi) const;
  float coat_pdf(const Vec3& wo, const Vec3& wi) const;
  float coat_probability(float mu_o) const;
  SampledSpectrum absorption(float mu) const;  // along the direction refracted from outside cosine mu

  CoatConstants c_;
  TrowbridgeReitz mf_;
  SampledSpectrum r_, tau_, k_;
};

}  // namespace eyetrace
