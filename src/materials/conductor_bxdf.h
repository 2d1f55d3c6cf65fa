// A metal: specular or Trowbridge-Reitz rough reflection with the Fresnel reflectance of a
// complex index eta + i k, per SampledSpectrum channel, as pbrt-v4's ConductorBxDF.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "materials/bxdf_util.h"
#include "materials/fresnel.h"
#include "materials/microfacet.h"

namespace eyetrace {

class ConductorBxDF {
 public:
  ConductorBxDF(const TrowbridgeReitz& mf, const SampledSpectrum& eta, const SampledSpectrum& k)
      : mf_(mf), eta_(eta), k_(k) {}

  unsigned flags() const { return kReflection | (mf_.effectively_smooth() ? kSpecular : kGlossy); }

  std::optional<BSDFSample> sample_f(const Vec3& wo, float /*uc*/, Vec2 u) const {
    if (wo.z == 0.f) return std::nullopt;
    BSDFSample s;
    if (mf_.effectively_smooth()) {
      s.wi = Vec3(-wo.x, -wo.y, wo.z);
      s.f = fresnel_complex(std::abs(s.wi.z), eta_, k_) / std::abs(s.wi.z);
      s.pdf = 1.f;
      s.flags = kReflection | kSpecular;
      return s;
    }
    Vec3 wm = mf_.sample_wm(wo, u);
    s.wi = reflect(wo, wm);
    if (!same_hemisphere(wo, s.wi)) return std::nullopt;
    s.f = f(wo, s.wi);
    s.pdf = pdf(wo, s.wi);
    s.flags = kReflection | kGlossy;
    if (!(s.pdf > 0.f)) return std::nullopt;
    return s;
  }

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const {
    Vec3 wm;
    if (mf_.effectively_smooth() || !half_vector(wo, wi, &wm)) return SampledSpectrum(0.f);
    SampledSpectrum fr = fresnel_complex(std::abs(glm::dot(wo, wm)), eta_, k_);
    return mf_.D(wm) * mf_.G(wo, wi) * fr / (4.f * std::abs(wi.z) * std::abs(wo.z));
  }

  float pdf(const Vec3& wo, const Vec3& wi) const {
    Vec3 wm;
    if (mf_.effectively_smooth() || !half_vector(wo, wi, &wm)) return 0.f;
    return mf_.pdf(wo, wm) / (4.f * std::abs(glm::dot(wo, wm)));
  }

 private:
  static bool half_vector(const Vec3& wo, const Vec3& wi, Vec3* wm) {
    if (!same_hemisphere(wo, wi) || wo.z == 0.f || wi.z == 0.f) return false;
    Vec3 h = wo + wi;
    float len2 = glm::dot(h, h);
    if (!(len2 > 0.f)) return false;
    h /= std::sqrt(len2);
    *wm = h.z < 0.f ? -h : h;
    return true;
  }

  TrowbridgeReitz mf_;
  SampledSpectrum eta_, k_;
};

}  // namespace eyetrace
