#include "materials/coated_conductor_bxdf.h"

#include "materials/bxdf_util.h"
#include "materials/coat_lobe.h"
#include "materials/fresnel.h"

namespace eyetrace {

CoatedConductorBxDF::CoatedConductorBxDF(float eta, const TrowbridgeReitz& coat, const TrowbridgeReitz& metal,
                                         const SampledSpectrum& metal_eta, const SampledSpectrum& metal_k,
                                         const SampledSpectrum& tau)
    : eta_(eta > 0.f && std::isfinite(eta) ? eta : 1.f),
      coat_(coat),
      metal_(metal),
      metal_bxdf_(metal, metal_eta, metal_k),
      metal_eta_(metal_eta),
      metal_k_(metal_k),
      tau_(clamp_non_negative(tau, 0.f)) {}

unsigned CoatedConductorBxDF::flags() const {
  if (both_smooth()) return kReflection | kSpecular;
  // One smooth layer adds a specular lobe to the other's glossy one.
  const bool specular = coat_.effectively_smooth() || metal_.effectively_smooth();
  return kReflection | kGlossy | (specular ? kSpecular : 0u);
}

float CoatedConductorBxDF::fresnel(float mu) const { return fresnel_dielectric(std::abs(mu), eta_); }

bool CoatedConductorBxDF::inside(const Vec3& w, Vec3* w_in) const {
  const float sin2 = (w.x * w.x + w.y * w.y) / (eta_ * eta_);
  if (!(sin2 < 1.f)) return false;  // a coat thinner than outside reflects it all (F = 1)
  *w_in = Vec3(w.x / eta_, w.y / eta_, std::sqrt(1.f - sin2));
  return true;
}

bool CoatedConductorBxDF::outside(const Vec3& w_in, Vec3* w) const {
  const float sin2 = (w_in.x * w_in.x + w_in.y * w_in.y) * (eta_ * eta_);
  if (!(sin2 < 1.f)) return false;  // beyond the critical angle: reflected back in, lost here
  *w = Vec3(w_in.x * eta_, w_in.y * eta_, std::sqrt(1.f - sin2));
  return w->z > 0.f;
}

SampledSpectrum CoatedConductorBxDF::absorption(float mu_in) const {
  if (is_black(tau_)) return SampledSpectrum(1.f);
  if (!(mu_in > 0.f)) return SampledSpectrum(0.f);
  return exp(tau_ * (-1.f / mu_in));
}

SampledSpectrum CoatedConductorBxDF::smooth_base(float mu) const {
  Vec3 w_in;
  if (!inside(Vec3(std::sqrt(std::max(0.f, 1.f - mu * mu)), 0.f, mu), &w_in)) return SampledSpectrum(0.f);
  const float f = fresnel(mu), t = 1.f - f;
  const SampledSpectrum a = absorption(w_in.z);
  const SampledSpectrum rb = fresnel_complex(w_in.z, metal_eta_, metal_k_) * a * a;
  // The series T^2 Rb sum (F Rb)^j: F < 1 wherever light enters, and Rb <= 1.
  SampledSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = t * t * rb[i] / (1.f - f * rb[i]);
  return out;
}

SampledSpectrum CoatedConductorBxDF::smooth_reflectance(float mu) const {
  return SampledSpectrum(fresnel(mu)) + smooth_base(mu);
}

// Lobes are chosen in proportion to a rough estimate of their energy at mu_o.
float CoatedConductorBxDF::coat_probability(float mu) const {
  const float f = fresnel(mu);
  Vec3 w_in;
  float base = 0.f;
  if (inside(Vec3(std::sqrt(std::max(0.f, 1.f - mu * mu)), 0.f, mu), &w_in))
    base = (1.f - f) * (fresnel_complex(w_in.z, metal_eta_, metal_k_) * absorption(w_in.z)).average();
  return f + base > 0.f ? f / (f + base) : 1.f;
}

// Two-sided: a direction pair below the surface is mirrored above it.
SampledSpectrum CoatedConductorBxDF::f(Vec3 wo, Vec3 wi) const {
  if (!same_hemisphere(wo, wi) || wo.z == 0.f) return SampledSpectrum(0.f);
  if (wo.z < 0.f) wo.z = -wo.z, wi.z = -wi.z;
  SampledSpectrum out(rough_coat_f(coat_, eta_, wo, wi));
  Vec3 wo_in, wi_in;
  if (metal_.effectively_smooth() || !inside(wo, &wo_in) || !inside(wi, &wi_in)) return out;
  const float t = (1.f - fresnel(wo.z)) * (1.f - fresnel(wi.z));
  return out + metal_bxdf_.f(wo_in, wi_in) * absorption(wo_in.z) * absorption(wi_in.z) * (t / (eta_ * eta_));
}

float CoatedConductorBxDF::pdf(Vec3 wo, Vec3 wi) const {
  if (!same_hemisphere(wo, wi) || wo.z == 0.f) return 0.f;
  if (wo.z < 0.f) wo.z = -wo.z, wi.z = -wi.z;
  const float pc = coat_probability(wo.z);
  float p = pc * rough_coat_pdf(coat_, wo, wi);
  Vec3 wo_in, wi_in;
  if (!metal_.effectively_smooth() && inside(wo, &wo_in) && inside(wi, &wi_in))
    // The metal's density over directions inside, times d w_in / d w = mu_i / (n^2 mu_i').
    p += (1.f - pc) * metal_bxdf_.pdf(wo_in, wi_in) * wi.z / (eta_ * eta_ * wi_in.z);
  return p;
}

std::optional<BSDFSample> CoatedConductorBxDF::sample_f(Vec3 wo, float uc, Vec2 u) const {
  if (wo.z == 0.f) return std::nullopt;
  const bool flip = wo.z < 0.f;
  if (flip) wo.z = -wo.z;
  BSDFSample s;
  const Vec3 mirror(-wo.x, -wo.y, wo.z);
  const float pc = coat_probability(wo.z);
  if (both_smooth()) {
    // One direction for both layers: their sum, sampled with certainty.
    s = {smooth_reflectance(wo.z) / wo.z, mirror, 1.f, kReflection | kSpecular};
  } else if (uc < pc && coat_.effectively_smooth()) {
    s = {SampledSpectrum(fresnel(wo.z) / wo.z), mirror, pc, kReflection | kSpecular};
  } else if (uc >= pc && metal_.effectively_smooth()) {
    s = {smooth_base(wo.z) / wo.z, mirror, 1.f - pc, kReflection | kSpecular};
  } else {
    if (uc < pc) {
      s.wi = reflect(wo, coat_.sample_wm(wo, u));
    } else {
      Vec3 wo_in, wi_in;
      if (!inside(wo, &wo_in)) return std::nullopt;
      std::optional<BSDFSample> m = metal_bxdf_.sample_f(wo_in, 0.5f, u);
      if (!m || !outside(m->wi, &s.wi)) return std::nullopt;
    }
    if (s.wi.z <= 0.f) return std::nullopt;
    s.f = f(wo, s.wi);
    s.pdf = pdf(wo, s.wi);
    s.flags = kReflection | kGlossy;
  }
  if (flip) s.wi.z = -s.wi.z;
  if (!(s.pdf > 0.f) || !is_finite(s.f)) return std::nullopt;
  return s;
}

}  // namespace eyetrace
