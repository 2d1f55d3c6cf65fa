// Small helpers shared by the BxDFs (local frame, +z = shading normal).
#pragma once
#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

inline bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.f; }

// Reflectances from textures may be out of range or non-finite; a BxDF must not amplify
// energy or emit NaN, so clamp to [0, 1] and map non-finite channels to 0.
inline SampledSpectrum clamp_unit(const SampledSpectrum& c) {
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) r[i] = std::isfinite(c[i]) ? std::clamp(c[i], 0.f, 1.f) : 0.f;
  return r;
}

// Non-negative and finite (for indices of refraction and absorption coefficients).
inline SampledSpectrum clamp_non_negative(const SampledSpectrum& c, float fallback) {
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) r[i] = std::isfinite(c[i]) ? std::max(c[i], 0.f) : fallback;
  return r;
}

}  // namespace eyetrace
