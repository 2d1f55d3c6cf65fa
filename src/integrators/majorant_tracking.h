// Sampling tentative collisions against a medium's majorants (pbrt-v4's SampleT_maj, PBR 4th
// ed. section 14.1.5): along each majorant segment, distances are drawn with density
// sigma_maj[0] exp(-sigma_maj[0] t) (the hero wavelength's majorant); at each point the
// callback gets the medium's properties there, the segment's majorant and T_maj, the majorant
// transmittance from the previous point (per wavelength), and says whether to go on. Returns
// T_maj from the last point to the end of the ray (1 if the callback stopped). Delta tracking
// (the path) and ratio tracking (shadow rays) are both callbacks.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/medium.h"
#include "samplers/hash.h"

namespace eyetrace {

// Uniform numbers for the decisions after the first along a tracked ray (pbrt-v4 uses an RNG
// there too): a path then takes a fixed number of the sampler's dimensions however many null
// collisions it meets. A counter hashed by mix_bits (SplitMix64's finaliser).
class TrackingRng {
 public:
  explicit TrackingRng(uint64_t seed) : state_(mix_bits(seed)) {}
  float uniform() {
    state_ += 0x9e3779b97f4a7c15ull;
    return hash_to_unit_float(mix_bits(state_));
  }

 private:
  uint64_t state_;
};

// exp(-sigma dt) per wavelength; an infinite dt is taken as the largest float, so that a
// wavelength with sigma 0 keeps 1 (0 * inf would be NaN) and the others reach 0.
inline SampledSpectrum majorant_transmittance(const SampledSpectrum& sigma, float dt) {
  if (std::isinf(dt)) dt = std::numeric_limits<float>::max();
  SampledSpectrum T;
  for (int i = 0; i < kSpectrumSamples; ++i) T[i] = std::exp(-dt * sigma[i]);
  return T;
}

// `ray` has a unit direction; t_max is where it ends (a surface, or infinity).
template <typename Callback>
SampledSpectrum sample_majorants(const Medium& medium, const Ray& ray, float t_max, float u, TrackingRng& rng,
                                 const SampledWavelengths& lambda, Callback&& callback) {
  MajorantIterator it = medium.majorants(ray, t_max, lambda);
  SampledSpectrum T_maj(1.f);
  while (const std::optional<MajorantSegment> seg = it.next()) {
    if (seg->sigma_maj[0] == 0.f) {  // the hero samples nothing here; the others are attenuated
      T_maj *= majorant_transmittance(seg->sigma_maj, seg->t_max - seg->t_min);
      continue;
    }
    float t_min = seg->t_min;
    for (;;) {
      const float t = t_min - std::log1p(-u) / seg->sigma_maj[0];
      u = rng.uniform();
      if (!(t < seg->t_max)) {
        T_maj *= majorant_transmittance(seg->sigma_maj, seg->t_max - t_min);
        break;
      }
      T_maj *= majorant_transmittance(seg->sigma_maj, t - t_min);
      const Vec3 p = ray.at(t);
      if (!callback(p, medium.properties(p, lambda), seg->sigma_maj, T_maj)) return SampledSpectrum(1.f);
      T_maj = SampledSpectrum(1.f);
      t_min = t;
    }
  }
  return T_maj;
}

}  // namespace eyetrace
