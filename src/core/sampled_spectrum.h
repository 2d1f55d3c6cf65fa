// What one camera sample carries: values at a few wavelengths (SampledSpectrum) and those
// wavelengths with the density they were drawn with (SampledWavelengths). This is pbrt-v4's
// hero-wavelength scheme (Wilkie et al. 2014): one uniform number picks the first wavelength,
// the others follow at equal steps of the sampling CDF, so the four are stratified and each
// on its own is distributed by the same density.
#pragma once
#include <array>
#include <cmath>

namespace eyetrace {

inline constexpr int kSpectrumSamples = 4;
// The wavelength range light transport samples (pbrt-v4's visible range).
inline constexpr float kLambdaMin = 360.f, kLambdaMax = 830.f;

class SampledSpectrum {
 public:
  SampledSpectrum() = default;
  explicit SampledSpectrum(float c) { v_.fill(c); }

  float operator[](int i) const { return v_[i]; }
  float& operator[](int i) { return v_[i]; }

#define EYETRACE_SPECTRUM_OP(op)                                                                         \
  SampledSpectrum& operator op##=(const SampledSpectrum& s) {                                            \
    for (int i = 0; i < kSpectrumSamples; ++i) v_[i] op## = s.v_[i];                                     \
    return *this;                                                                                        \
  }                                                                                                      \
  SampledSpectrum& operator op##=(float a) {                                                             \
    for (int i = 0; i < kSpectrumSamples; ++i) v_[i] op## = a;                                           \
    return *this;                                                                                        \
  }                                                                                                      \
  friend SampledSpectrum operator op(SampledSpectrum a, const SampledSpectrum& b) { return a op## = b; } \
  friend SampledSpectrum operator op(SampledSpectrum a, float b) { return a op## = b; }
  EYETRACE_SPECTRUM_OP(+)
  EYETRACE_SPECTRUM_OP(-)
  EYETRACE_SPECTRUM_OP(*)
#undef EYETRACE_SPECTRUM_OP
  friend SampledSpectrum operator*(float a, SampledSpectrum b) { return b *= a; }
  SampledSpectrum& operator/=(float a) {
    const float inv = 1.f / a;
    for (float& x : v_) x *= inv;
    return *this;
  }
  friend SampledSpectrum operator/(SampledSpectrum a, float b) { return a /= b; }
  // Division that gives 0 where the divisor is 0 (a terminated wavelength's density).
  friend SampledSpectrum safe_div(SampledSpectrum a, const SampledSpectrum& b) {
    for (int i = 0; i < kSpectrumSamples; ++i) a.v_[i] = b.v_[i] != 0.f ? a.v_[i] / b.v_[i] : 0.f;
    return a;
  }

  bool is_black() const {
    for (float x : v_)
      if (x != 0.f) return false;
    return true;
  }
  bool is_finite() const {
    for (float x : v_)
      if (!std::isfinite(x)) return false;
    return true;
  }
  float max_component() const {
    float m = v_[0];
    for (float x : v_) m = std::fmax(m, x);
    return m;
  }
  float average() const {
    float s = 0.f;
    for (float x : v_) s += x;
    return s / kSpectrumSamples;
  }

 private:
  std::array<float, kSpectrumSamples> v_{};
};

inline SampledSpectrum exp(SampledSpectrum s) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::exp(s[i]);
  return s;
}
inline SampledSpectrum sqrt(SampledSpectrum s) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::sqrt(s[i]);
  return s;
}
inline SampledSpectrum min(SampledSpectrum s, float m) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::fmin(s[i], m);
  return s;
}
inline bool is_black(const SampledSpectrum& s) { return s.is_black(); }
inline bool is_finite(const SampledSpectrum& s) { return s.is_finite(); }
inline float max_component(const SampledSpectrum& s) { return s.max_component(); }

// Density pbrt-v4 samples visible wavelengths with (a sech^2 lobe around 538 nm that follows
// the CIE Y curve's width), normalised over [360, 830] nm.
inline float visible_wavelength_pdf(float lambda) {
  if (lambda < kLambdaMin || lambda > kLambdaMax) return 0.f;
  const float c = std::cosh(0.0072f * (lambda - 538.f));
  return 0.0039398042f / (c * c);
}
// Its inverse CDF: u in [0,1) -> lambda in [360, 830].
inline float sample_visible_wavelength(float u) {
  return 538.f - 138.888889f * std::atanh(0.85691062f - 1.82750197f * u);
}

// The tabulated inverse of the visible-wavelength CDF: u in [0, 1) -> lambda and its density.
void visible_wavelength_from_table(float u, float* lambda, float* pdf);

class SampledWavelengths {
 public:
  // Four stratified wavelengths from one uniform number (the sampler's wavelength dimension).
  // The inverse CDF is tabulated (core/sampled_spectrum.cpp) and interpolated linearly, so a
  // wavelength costs a table lookup instead of an atanh; the density returned is that of the
  // tabulated sampler itself (piecewise constant, within 0.5 % of the formula above).
  static SampledWavelengths sample_visible(float u) {
    SampledWavelengths w;
    for (int i = 0; i < kSpectrumSamples; ++i) visible_wavelength_from_table(rotated(u, i), &w.lambda_[i], &w.pdf_[i]);
    return w;
  }
  // The uniform number of wavelength i of the set drawn from u: sample_visible(rotated(u, i))
  // is the same set with wavelength i first (its hero).
  static float rotated(float u, int i) {
    float up = u + float(i) / kSpectrumSamples;
    if (up >= 1.f) up -= 1.f;
    return up;
  }
  // Uniform over [lo, hi] with the same stratification (tests; spectral films of a band).
  static SampledWavelengths sample_uniform(float u, float lo = kLambdaMin, float hi = kLambdaMax) {
    SampledWavelengths w;
    const float delta = (hi - lo) / kSpectrumSamples;
    w.lambda_[0] = lo + u * (hi - lo);
    for (int i = 1; i < kSpectrumSamples; ++i) {
      w.lambda_[i] = w.lambda_[i - 1] + delta;
      if (w.lambda_[i] > hi) w.lambda_[i] = lo + (w.lambda_[i] - hi);
    }
    for (float& p : w.pdf_) p = 1.f / (hi - lo);
    return w;
  }

  float operator[](int i) const { return lambda_[i]; }
  // The densities as a spectrum, to divide estimates by (0 for a terminated wavelength).
  SampledSpectrum pdf() const {
    SampledSpectrum p;
    for (int i = 0; i < kSpectrumSamples; ++i) p[i] = pdf_[i];
    return p;
  }

  // Keeps only the first (hero) wavelength: what a path does when it splits by wavelength
  // (dispersion). Its density becomes that of being any of the four, so the estimate stays
  // unbiased: the hero alone now stands for the whole set.
  void terminate_secondary() {
    if (secondary_terminated()) return;
    for (int i = 1; i < kSpectrumSamples; ++i) pdf_[i] = 0.f;
    pdf_[0] /= kSpectrumSamples;
  }
  bool secondary_terminated() const {
    for (int i = 1; i < kSpectrumSamples; ++i)
      if (pdf_[i] != 0.f) return false;
    return true;
  }

 private:
  std::array<float, kSpectrumSamples> lambda_{}, pdf_{};
};

}  // namespace eyetrace
