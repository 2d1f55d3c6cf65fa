// Fresnel reflectance of smooth interfaces and the refraction law, in a local frame whose
// +z is the surface normal. Unpolarised light: the mean of the s and p reflectances.
#pragma once
#include <complex>

#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

// Reflectance of a dielectric interface with relative index eta = n_inside / n_outside
// (inside is -z). cos_i < 0 means the light arrives from inside. 1 beyond the critical angle.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, -1.f, 1.f);
  if (cos_i < 0.f) {
    eta = 1.f / eta;
    cos_i = -cos_i;
  }
  float sin2_t = (1.f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.f) return 1.f;
  float cos_t = safe_sqrt(1.f - sin2_t);
  float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_parl * r_parl + r_perp * r_perp);
}

// Reflectance of a conductor with complex index eta + i k (relative to the outside medium).
inline float fresnel_complex(float cos_i, float eta, float k) {
  using C = std::complex<float>;
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  C n(eta, k);
  C sin2_t = C(1.f - cos_i * cos_i) / (n * n);
  C cos_t = std::sqrt(C(1.f) - sin2_t);
  C r_parl = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  C r_perp = (C(cos_i) - n * cos_t) / (C(cos_i) + n * cos_t);
  return 0.5f * (std::norm(r_parl) + std::norm(r_perp));
}

inline SampledSpectrum fresnel_complex(float cos_i, const SampledSpectrum& eta, const SampledSpectrum& k) {
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) r[i] = fresnel_complex(cos_i, eta[i], k[i]);
  return r;
}

// Refracts wi (pointing away from the surface) through normal n, eta = n_inside/n_outside
// with n on the outside. On success *etap is the index ratio actually crossed. False on
// total internal reflection.
inline bool refract(const Vec3& wi, Vec3 n, float eta, float* etap, Vec3* wt) {
  float cos_i = glm::dot(n, wi);
  if (cos_i < 0.f) {
    eta = 1.f / eta;
    cos_i = -cos_i;
    n = -n;
  }
  float sin2_t = std::max(0.f, 1.f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.f) return false;
  float cos_t = safe_sqrt(1.f - sin2_t);
  *wt = -wi / eta + (cos_i / eta - cos_t) * n;
  if (etap) *etap = eta;
  return true;
}

inline Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + 2.f * glm::dot(wo, n) * n; }

}  // namespace eyetrace
