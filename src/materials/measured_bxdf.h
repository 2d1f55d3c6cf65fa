// pbrt-v4's MeasuredBxDF: an RGL measured BRDF (measured_brdf.h) evaluated and sampled as
// Dupuy & Jakob (2018) and pbrt-v4 do. In the local frame (+z the normal, +x along dpdu):
//   f(wo, wi) = S(u, wo, lambda) D(wm) / (4 sigma(wo) cos theta_i),
// with wm the half vector, D the tabulated NDF, sigma the projected area, and S the spectral
// table, read at u = R^-1(wm): the point of the sample square the visible-normal warp R sends to
// wm. Sampling warps u by the luminance table, then by R, and reflects wo about wm.
// Reflection only; a direction pair below the surface is mirrored to the top as in pbrt-v4.
// Not reciprocal by construction (S and R are tabulated per wo); a faithful measurement is
// reciprocal to within its interpolation error.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "core/sampled_spectrum.h"
#include "materials/measured_brdf.h"

namespace eyetrace {

class MeasuredBxDF {
 public:
  // `brdf` must outlive the BxDF (the material holds it).
  MeasuredBxDF(const MeasuredBRDF* brdf, const SampledWavelengths& lambda) : brdf_(brdf), lambda_(lambda) {}

  unsigned flags() const { return kReflection | kGlossy; }
  SampledSpectrum f(Vec3 wo, Vec3 wi) const;
  std::optional<BSDFSample> sample_f(Vec3 wo, float uc, Vec2 u) const;
  float pdf(Vec3 wo, Vec3 wi) const;

 private:
  // S at sample-square point u for wo's angles, per wavelength (negative values count as 0).
  SampledSpectrum spectrum(Vec2 u, float phi_o, float theta_o) const;

  const MeasuredBRDF* brdf_;
  SampledWavelengths lambda_;
};

}  // namespace eyetrace
