// The directional term Sw of pbrt-v4's separable BSSRDF, where subsurface light leaves the
// surface: f = (1 - Fr(cos wi, eta)) / (c pi) with c = 1 - 2 FresnelMoment1(1 / eta), so
// that the cosine-weighted integral of f over the hemisphere is 1 (the normalisation), times
// eta^2 for radiance (pbrt-v4's NormalizedFresnelBxDF in TransportMode::Radiance).
// Reflection on the side of wo only, cosine-sampled.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "core/sampling.h"
#include "materials/bssrdf_table.h"
#include "materials/bxdf_util.h"
#include "materials/fresnel.h"

namespace eyetrace {

class NormalizedFresnelBxDF {
 public:
  explicit NormalizedFresnelBxDF(float eta)
      : eta_(eta), scale_(eta * eta / ((1.f - 2.f * fresnel_moment1(1.f / eta)) * kPi)) {}

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return SampledSpectrum(0.f);
    return SampledSpectrum((1.f - fresnel_dielectric(wi.z, eta_)) * scale_);
  }
  std::optional<BSDFSample> sample_f(const Vec3& wo, float /*uc*/, Vec2 u) const {
    Vec3 wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.f) wi.z = -wi.z;
    BSDFSample s;
    s.wi = wi;
    s.pdf = pdf(wo, wi);
    if (!(s.pdf > 0.f)) return std::nullopt;
    s.f = f(wo, wi);
    s.flags = kReflection | kDiffuse;
    return s;
  }
  float pdf(const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.f;
  }
  unsigned flags() const { return kReflection | kDiffuse; }

 private:
  float eta_, scale_;
};

}  // namespace eyetrace
