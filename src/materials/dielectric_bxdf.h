// A dielectric interface (glass, water, the cornea): specular or Trowbridge-Reitz rough
// reflection and transmission, chosen in proportion to the Fresnel reflectance, as pbrt-v4's
// DielectricBxDF. Transmitted radiance is scaled by 1/eta^2 (radiance, not importance).
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "materials/bxdf_util.h"
#include "materials/fresnel.h"
#include "materials/microfacet.h"

namespace eyetrace {

class DielectricBxDF {
 public:
  // eta: index inside (-z side) over index outside.
  DielectricBxDF(float eta, const TrowbridgeReitz& mf) : eta_(eta), mf_(mf) {}

  unsigned flags() const {
    unsigned f = eta_ == 1.f ? unsigned(kTransmission) : unsigned(kReflection | kTransmission);
    return f | (is_smooth() ? kSpecular : kGlossy);
  }
  float eta() const { return eta_; }

  std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2 u) const {
    return is_smooth() ? sample_smooth(wo, uc) : sample_rough(wo, uc, u);
  }

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const {
    Half h;
    if (is_smooth() || !half_vector(wo, wi, &h)) return SampledSpectrum(0.f);
    float fr = fresnel_dielectric(glm::dot(wo, h.wm), eta_);
    float g = mf_.G(wo, wi), d = mf_.D(h.wm);
    if (h.reflect) return SampledSpectrum(d * g * fr / std::abs(4.f * wi.z * wo.z));
    float denom = sqr(glm::dot(wi, h.wm) + glm::dot(wo, h.wm) / h.etap) * wi.z * wo.z;
    float ft = d * (1.f - fr) * g * std::abs(glm::dot(wi, h.wm) * glm::dot(wo, h.wm) / denom);
    return SampledSpectrum(ft / sqr(h.etap));
  }

  float pdf(const Vec3& wo, const Vec3& wi) const {
    Half h;
    if (is_smooth() || !half_vector(wo, wi, &h)) return 0.f;
    float r = fresnel_dielectric(glm::dot(wo, h.wm), eta_), t = 1.f - r;
    if (h.reflect) return mf_.pdf(wo, h.wm) / (4.f * std::abs(glm::dot(wo, h.wm))) * r / (r + t);
    float denom = sqr(glm::dot(wi, h.wm) + glm::dot(wo, h.wm) / h.etap);
    float dwm_dwi = std::abs(glm::dot(wi, h.wm)) / denom;
    return mf_.pdf(wo, h.wm) * dwm_dwi * t / (r + t);
  }

 private:
  struct Half {
    Vec3 wm;
    float etap;
    bool reflect;
  };

  bool is_smooth() const { return eta_ == 1.f || mf_.effectively_smooth(); }

  // The generalised half vector of a reflected or refracted pair, facing +z; false for
  // degenerate pairs and for pairs that only back-facing microfacets could connect.
  bool half_vector(const Vec3& wo, const Vec3& wi, Half* h) const {
    float cos_o = wo.z, cos_i = wi.z;
    if (cos_i == 0.f || cos_o == 0.f) return false;
    h->reflect = cos_i * cos_o > 0.f;
    h->etap = h->reflect ? 1.f : (cos_o > 0.f ? eta_ : 1.f / eta_);
    Vec3 wm = wi * h->etap + wo;
    float len2 = glm::dot(wm, wm);
    if (!(len2 > 0.f)) return false;
    wm /= std::sqrt(len2);
    if (wm.z < 0.f) wm = -wm;
    if (glm::dot(wm, wi) * cos_i < 0.f || glm::dot(wm, wo) * cos_o < 0.f) return false;
    h->wm = wm;
    return true;
  }

  std::optional<BSDFSample> sample_smooth(const Vec3& wo, float uc) const {
    float r = fresnel_dielectric(wo.z, eta_), t = 1.f - r;
    BSDFSample s;
    if (uc < r / (r + t)) {
      s.wi = Vec3(-wo.x, -wo.y, wo.z);
      s.f = SampledSpectrum(r / std::abs(s.wi.z));
      s.pdf = r / (r + t);
      s.flags = kReflection | kSpecular;
      return s;
    }
    float etap;
    if (!refract(wo, Vec3(0.f, 0.f, 1.f), eta_, &etap, &s.wi) || s.wi.z == 0.f) return std::nullopt;
    s.f = SampledSpectrum(t / std::abs(s.wi.z) / sqr(etap));
    s.pdf = t / (r + t);
    s.flags = kTransmission | kSpecular;
    s.eta = etap;
    return s;
  }

  std::optional<BSDFSample> sample_rough(const Vec3& wo, float uc, Vec2 u) const {
    if (wo.z == 0.f) return std::nullopt;
    Vec3 wm = mf_.sample_wm(wo, u);
    float r = fresnel_dielectric(glm::dot(wo, wm), eta_), t = 1.f - r;
    BSDFSample s;
    if (uc < r / (r + t)) {
      s.wi = reflect(wo, wm);
      if (!same_hemisphere(wo, s.wi)) return std::nullopt;
      s.flags = kReflection | kGlossy;
    } else {
      float etap;
      if (!refract(wo, wm, eta_, &etap, &s.wi) || same_hemisphere(wo, s.wi) || s.wi.z == 0.f) return std::nullopt;
      s.flags = kTransmission | kGlossy;
      s.eta = etap;
    }
    // f() and pdf() recompute the half vector from (wo, wi): sample and evaluation agree.
    s.f = f(wo, s.wi);
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.f)) return std::nullopt;
    return s;
  }

  float eta_;
  TrowbridgeReitz mf_;
};

}  // namespace eyetrace
