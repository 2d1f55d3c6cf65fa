// Helpers for tests of spectral quantities: a fixed set of sampled wavelengths, and the
// spectra that RGB values stand for (core/spectrum.h), so a test can state what a light or a
// BSDF must return at those wavelengths.
#pragma once
#include "core/spectrum.h"

namespace eyetrace::test {

// Four stratified visible wavelengths: about 494, 559, 635 and 398 nm for u = 0.3.
inline SampledWavelengths wavelengths(float u = 0.3f) { return SampledWavelengths::sample_visible(u); }

// An emission given as RGB, at lambda.
inline SampledSpectrum emission(const RGB& rgb, const SampledWavelengths& lambda) {
  return Spectrum::from_rgb(rgb, SpectrumType::Illuminant).sample(lambda);
}
inline SampledSpectrum emission(float grey, const SampledWavelengths& lambda) { return emission(RGB(grey), lambda); }
// A reflectance given as RGB, at lambda.
inline SampledSpectrum albedo(const RGB& rgb, const SampledWavelengths& lambda) {
  return Spectrum::from_rgb(rgb, SpectrumType::Albedo).sample(lambda);
}

// A spectrum with three chosen values (the fourth repeats the third): BxDF tests that treat
// wavelengths as independent channels, as they treated RGB.
inline SampledSpectrum channels(float a, float b, float c) {
  SampledSpectrum s(c);
  s[0] = a;
  s[1] = b;
  return s;
}
inline SampledSpectrum max0(SampledSpectrum s) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::max(s[i], 0.f);
  return s;
}

inline bool same(const SampledSpectrum& a, const SampledSpectrum& b, float rel = 1e-6f) {
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (std::abs(a[i] - b[i]) > rel * std::max(std::abs(a[i]), std::abs(b[i]))) return false;
  return true;
}

// Luminance Y of a spectrum sampled at lambda, by integrating over many wavelength sets: the
// spectrum is given as a function of the set.
template <typename F>
float luminance_of(F&& spectrum_at, int sets = 4096) {
  double y = 0.0;
  for (int i = 0; i < sets; ++i) {
    SampledWavelengths l = SampledWavelengths::sample_visible((i + 0.5f) / sets);
    y += sampled_to_xyz(spectrum_at(l), l).y;
  }
  return float(y / sets);
}

}  // namespace eyetrace::test
