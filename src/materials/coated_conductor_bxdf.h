// A metal under a dielectric coat (pbrt-v4's "coatedconductor"), in closed form like
// coated_diffuse_bxdf.h instead of pbrt-v4's stochastic layered random walk. With n the coat's
// index, F the coat's Fresnel reflectance at the outside angle, T = 1 - F, w' the direction
// refracted into the coat (tangential part / n), A(mu') = exp(-tau / mu') the coat's absorption
// along it and f_c the metal's BRDF inside the coat (its index relative to the coat, as
// pbrt-v4 divides it by n):
//
//   f = f_coat + f_base
//   f_coat = the coat's reflection (coat_lobe.h: specular F, or the rough lobe)
//   f_base = T(mu_o) T(mu_i) f_c(w_o', w_i') A(mu_o') A(mu_i') / n^2      (a rough metal)
//   f_base = a mirror reflection of T^2 Rb / (1 - F Rb), Rb = R_c(mu') A(mu')^2  (a smooth metal:
//            the light reflected between metal and coat any number of times, all in one direction)
//
// The 1/n^2 is the radiance's: it grows by n^2 T into the coat and shrinks by T / n^2 out of
// it, and the solid angle inside is mu dw / (n^2 mu'). Energy: the base's albedo is at most
// T(mu_o) (the metal's albedo <= 1 inside, substituting dw = n^2 mu' dw' / mu), the coat's at
// most F(mu_o); reciprocal, since every factor is symmetric in o and i. Light the rough metal
// sends beyond the coat's critical angle stays inside and is lost, and light the coat's
// underside reflects back down is not followed (pbrt-v4's walk follows both: against pbrt-v4 a
// rough coat on rough copper has the same luminance within 0.3 % but is less saturated, most at
// the silhouette; tests/render/pbrt_v4_reference_slowtest.cpp); the rough coat over a smooth metal
// refracts at the macro surface. Two-sided, as pbrt-v4's.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "materials/conductor_bxdf.h"
#include "materials/microfacet.h"

namespace eyetrace {

class CoatedConductorBxDF {
 public:
  // eta: the coat's index; metal_eta, metal_k: the metal's, relative to the coat; tau: the
  // coat's optical thickness per channel.
  CoatedConductorBxDF(float eta, const TrowbridgeReitz& coat, const TrowbridgeReitz& metal,
                      const SampledSpectrum& metal_eta, const SampledSpectrum& metal_k, const SampledSpectrum& tau);

  unsigned flags() const;
  SampledSpectrum f(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  std::optional<BSDFSample> sample_f(Vec3 wo, float uc, Vec2 u) const;

  // The total reflectance of a smooth coat on a smooth metal at cosine mu (F + the base's
  // series), the one specular lobe's weight there; for tests.
  SampledSpectrum smooth_reflectance(float mu) const;

 private:
  float fresnel(float mu) const;
  // w refracted into the coat (both above the surface); false when it cannot enter (n < 1).
  bool inside(const Vec3& w, Vec3* w_in) const;
  bool outside(const Vec3& w_in, Vec3* w) const;
  SampledSpectrum absorption(float mu_in) const;
  SampledSpectrum smooth_base(float mu) const;  // T^2 Rb / (1 - F Rb)
  float coat_probability(float mu) const;
  bool both_smooth() const { return coat_.effectively_smooth() && metal_.effectively_smooth(); }

  float eta_;
  TrowbridgeReitz coat_, metal_;
  ConductorBxDF metal_bxdf_;
  SampledSpectrum metal_eta_, metal_k_, tau_;
};

}  // namespace eyetrace
