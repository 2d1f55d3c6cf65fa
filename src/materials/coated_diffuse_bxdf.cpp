#include "materials/coated_diffuse_bxdf.h"

#include "materials/coat_lobe.h"

namespace eyetrace {

CoatConstants CoatConstants::make(float eta) {
  CoatConstants c;
  c.eta = eta;
  c.n2 = std::max(eta * eta, 1.f);
  // Tbar = integral over [0, 1] of 2 mu (1 - F(mu)), midpoint rule; F is smooth on the
  // interior, and the rounding up keeps the energy bound (K uses Tbar).
  constexpr int n = 4096;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double mu = (i + 0.5) / n;
    sum += 2.0 * mu * (1.0 - fresnel_dielectric(float(mu), eta));
  }
  c.t_mean = std::min(1.f, float(sum / n) + 1e-4f);
  return c;
}

CoatedDiffuseBxDF::CoatedDiffuseBxDF(const CoatConstants& c, const TrowbridgeReitz& mf,
                                     const SampledSpectrum& reflectance, const SampledSpectrum& tau)
    : c_(c), mf_(mf), r_(clamp_unit(reflectance)), tau_(clamp_non_negative(tau, 0.f)) {
  SampledSpectrum a2 = exp(tau_ * -4.f);
  k_ = c_.n2 * (SampledSpectrum(1.f) - r_ * a2) + r_ * a2 * c_.t_mean;
}

SampledSpectrum CoatedDiffuseBxDF::absorption(float mu) const {
  float mu_in = safe_sqrt(1.f - (1.f - mu * mu) / sqr(c_.eta));
  if (is_black(tau_)) return SampledSpectrum(1.f);
  if (mu_in <= 0.f) return SampledSpectrum(0.f);
  return exp(tau_ * (-1.f / mu_in));
}

SampledSpectrum CoatedDiffuseBxDF::base(float mu_o, float mu_i) const {
  SampledSpectrum num = r_ * (1.f - fresnel(mu_o)) * (1.f - fresnel(mu_i)) * absorption(mu_o) * absorption(mu_i);
  SampledSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = k_[i] > 0.f ? num[i] / (kPi * k_[i]) : 0.f;
  return out;
}

float CoatedDiffuseBxDF::coat_f(const Vec3& wo, const Vec3& wi) const { return rough_coat_f(mf_, c_.eta, wo, wi); }

float CoatedDiffuseBxDF::coat_pdf(const Vec3& wo, const Vec3& wi) const { return rough_coat_pdf(mf_, wo, wi); }

// Lobes are chosen in proportion to their rough share of the reflected energy.
float CoatedDiffuseBxDF::coat_probability(float mu_o) const {
  float fr = fresnel(mu_o);
  float diffuse = (1.f - fr) * r_.average();
  return fr + diffuse > 0.f ? fr / (fr + diffuse) : 0.f;
}

// Two-sided: a direction pair below the surface is mirrored above it.
SampledSpectrum CoatedDiffuseBxDF::f(Vec3 wo, Vec3 wi) const {
  if (!same_hemisphere(wo, wi)) return SampledSpectrum(0.f);
  if (wo.z < 0.f) wo.z = -wo.z, wi.z = -wi.z;
  return base(wo.z, wi.z) + SampledSpectrum(coat_f(wo, wi));
}

float CoatedDiffuseBxDF::pdf(Vec3 wo, Vec3 wi) const {
  if (!same_hemisphere(wo, wi)) return 0.f;
  if (wo.z < 0.f) wo.z = -wo.z, wi.z = -wi.z;
  float pc = coat_probability(wo.z);
  return pc * coat_pdf(wo, wi) + (1.f - pc) * cosine_hemisphere_pdf(wi.z);
}

std::optional<BSDFSample> CoatedDiffuseBxDF::sample_f(Vec3 wo, float uc, Vec2 u) const {
  if (wo.z == 0.f) return std::nullopt;
  bool flip = wo.z < 0.f;
  if (flip) wo.z = -wo.z;
  float pc = coat_probability(wo.z);
  BSDFSample s;
  if (uc < pc && mf_.effectively_smooth()) {
    s.wi = Vec3(-wo.x, -wo.y, wo.z);
    s.f = SampledSpectrum(fresnel(wo.z) / s.wi.z);
    s.pdf = pc;
    s.flags = kReflection | kSpecular;
  } else {
    if (uc < pc) {
      s.wi = reflect(wo, mf_.sample_wm(wo, u));
      s.flags = kReflection | kGlossy;
    } else {
      s.wi = sample_cosine_hemisphere(u);
      s.flags = kReflection | kDiffuse;
    }
    if (s.wi.z <= 0.f) return std::nullopt;
    s.f = f(wo, s.wi);
    s.pdf = pdf(wo, s.wi);
  }
  if (flip) s.wi.z = -s.wi.z;
  if (!(s.pdf > 0.f)) return std::nullopt;
  return s;
}

SampledSpectrum CoatedDiffuseBxDF::albedo() const {
  // At normal incidence: the coat's F(1) plus the base's share of the rest.
  float f0 = fresnel(1.f);
  SampledSpectrum base_albedo;
  for (int i = 0; i < kSpectrumSamples; ++i) base_albedo[i] = k_[i] > 0.f ? r_[i] * c_.t_mean / k_[i] : 0.f;
  return SampledSpectrum(f0) + (1.f - f0) * base_albedo * absorption(1.f);
}

}  // namespace eyetrace
