// The dielectric coat's own reflection in eyetrace's closed-form coated materials
// (coated_diffuse_bxdf.h, coated_conductor_bxdf.h): for a rough coat the Trowbridge-Reitz lobe
// D G min(F(mu_o), F(mu_i)) / (4 mu_o mu_i), F the dielectric Fresnel reflectance at the macro
// angles (both directions above the surface, z > 0), and the density its sampling gives
// (visible normals, reflected). A smooth coat is a specular reflection of F(mu_o), which the
// materials sample themselves.
#pragma once
#include "core/math.h"
#include "materials/fresnel.h"
#include "materials/microfacet.h"

namespace eyetrace {

inline float rough_coat_f(const TrowbridgeReitz& mf, float eta, const Vec3& wo, const Vec3& wi) {
  if (mf.effectively_smooth()) return 0.f;
  Vec3 wm = wo + wi;
  const float len2 = glm::dot(wm, wm);
  if (!(len2 > 0.f)) return 0.f;
  wm /= std::sqrt(len2);
  const float fr = std::min(fresnel_dielectric(std::abs(wo.z), eta), fresnel_dielectric(std::abs(wi.z), eta));
  return mf.D(wm) * mf.G(wo, wi) * fr / (4.f * wo.z * wi.z);
}

inline float rough_coat_pdf(const TrowbridgeReitz& mf, const Vec3& wo, const Vec3& wi) {
  if (mf.effectively_smooth()) return 0.f;
  Vec3 wm = wo + wi;
  const float len2 = glm::dot(wm, wm);
  if (!(len2 > 0.f)) return 0.f;
  wm /= std::sqrt(len2);
  return mf.pdf(wo, wm) / (4.f * std::abs(glm::dot(wo, wm)));
}

}  // namespace eyetrace
