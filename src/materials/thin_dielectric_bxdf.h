// pbrt-v4's ThinDielectricBxDF: a thin slab of glass (a window pane). Light reflects at both
// faces any number of times; with R the single-face Fresnel reflectance and T = 1 - R, the sum of
// the geometric series gives R' = R + T^2 R / (1 - R^2) and T' = 1 - R' (no absorption). Both
// lobes are specular: the mirror direction and straight through (the slab's two refractions
// cancel), chosen with probabilities R' and T'.
#pragma once
#include <optional>

#include "core/bsdf.h"
#include "materials/fresnel.h"

namespace eyetrace {

class ThinDielectricBxDF {
 public:
  explicit ThinDielectricBxDF(float eta) : eta_(eta) {}

  SampledSpectrum f(const Vec3&, const Vec3&) const { return SampledSpectrum(0.f); }
  std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2) const {
    if (wo.z == 0.f) return std::nullopt;
    float r = fresnel_dielectric(std::abs(wo.z), eta_), t = 1.f - r;
    // R = 1 (a grazing ray, or eta making the face a mirror) needs no series: all reflects.
    if (r < 1.f) {
      r += t * t * r / (1.f - r * r);
      t = 1.f - r;
    }
    BSDFSample s;
    if (uc < r) {
      s.wi = Vec3(-wo.x, -wo.y, wo.z);
      s.f = SampledSpectrum(r / std::abs(wo.z));
      s.pdf = r;
      s.flags = kReflection | kSpecular;
    } else {
      s.wi = -wo;
      s.f = SampledSpectrum(t / std::abs(wo.z));
      s.pdf = t;
      s.flags = kTransmission | kSpecular;
    }
    if (!(s.pdf > 0.f)) return std::nullopt;
    return s;
  }
  float pdf(const Vec3&, const Vec3&) const { return 0.f; }
  unsigned flags() const { return kReflection | kTransmission | kSpecular; }

 private:
  float eta_;
};

}  // namespace eyetrace
