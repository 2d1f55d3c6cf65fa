// pbrt-v4's DiffuseTransmissionBxDF: f = R / pi for directions on wo's side of the surface and
// T / pi through it. Sampled by choosing reflection with probability max(R) / (max(R) + max(T))
// (transmission otherwise) and a cosine-distributed direction on that side, so the estimator
// f cos / pdf is R or T divided by the choice's probability.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "core/sampling.h"
#include "materials/bxdf_util.h"

namespace eyetrace {

class DiffuseTransmissionBxDF {
 public:
  DiffuseTransmissionBxDF(const SampledSpectrum& r, const SampledSpectrum& t) : r_(clamp_unit(r)), t_(clamp_unit(t)) {}

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const { return (same_hemisphere(wo, wi) ? r_ : t_) * kInvPi; }
  std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2 u) const {
    const float pr = r_.max_component(), pt = t_.max_component();
    if (!(pr + pt > 0.f)) return std::nullopt;
    const bool reflect = uc < pr / (pr + pt);
    Vec3 wi = sample_cosine_hemisphere(u);
    // The reflected direction on wo's side, the transmitted one on the other.
    if ((wo.z < 0.f) == reflect) wi.z = -wi.z;
    const float pdf = cosine_hemisphere_pdf(std::abs(wi.z)) * (reflect ? pr : pt) / (pr + pt);
    if (!(pdf > 0.f)) return std::nullopt;
    BSDFSample s;
    s.f = (reflect ? r_ : t_) * kInvPi;
    s.wi = wi;
    s.pdf = pdf;
    s.flags = (reflect ? kReflection : kTransmission) | kDiffuse;
    return s;
  }
  float pdf(const Vec3& wo, const Vec3& wi) const {
    const float pr = r_.max_component(), pt = t_.max_component();
    if (!(pr + pt > 0.f)) return 0.f;
    return cosine_hemisphere_pdf(std::abs(wi.z)) * (same_hemisphere(wo, wi) ? pr : pt) / (pr + pt);
  }
  unsigned flags() const {
    return (is_black(r_) ? 0u : unsigned(kReflection | kDiffuse)) |
           (is_black(t_) ? 0u : unsigned(kTransmission | kDiffuse));
  }

 private:
  SampledSpectrum r_, t_;
};

}  // namespace eyetrace
