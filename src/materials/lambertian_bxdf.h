// Ideal diffuse reflection, f = R / pi on both sides of the surface, sampled by a cosine
// distribution so that f cos / pdf = R exactly.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "core/sampling.h"
#include "materials/bxdf_util.h"

namespace eyetrace {

class LambertianBxDF {
 public:
  explicit LambertianBxDF(const SampledSpectrum& r) : r_(clamp_unit(r)) {}

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return SampledSpectrum(0.f);
    return r_ * kInvPi;
  }
  std::optional<BSDFSample> sample_f(const Vec3& wo, float /*uc*/, Vec2 u) const {
    Vec3 wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.f) wi.z = -wi.z;
    float pdf = cosine_hemisphere_pdf(std::abs(wi.z));
    if (!(pdf > 0.f)) return std::nullopt;
    BSDFSample s;
    s.f = r_ * kInvPi;
    s.wi = wi;
    s.pdf = pdf;
    s.flags = kReflection | kDiffuse;
    return s;
  }
  float pdf(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return 0.f;
    return cosine_hemisphere_pdf(std::abs(wi.z));
  }
  unsigned flags() const { return is_black(r_) ? 0u : unsigned(kReflection | kDiffuse); }

 private:
  SampledSpectrum r_;
};

}  // namespace eyetrace
