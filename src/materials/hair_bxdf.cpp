#include "materials/hair_bxdf.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "materials/fresnel.h"

namespace eyetrace {

namespace {

// I0, the modified Bessel function of the first kind of order 0, by its power series
// sum (x/2)^(2i) / (i!)^2, summed until a term no longer changes the float sum (used for
// x <= 12 here: at most about 30 terms).
float bessel_i0(float x) {
  static constexpr auto kInvSquares = [] {
    std::array<float, 40> t{};
    for (int i = 1; i < 40; ++i) t[i] = 1.f / float(i * i);
    return t;
  }();
  const float q = 0.25f * x * x;
  float term = 1.f, sum = 1.f;
  for (int i = 1; i < 40 && term > 1e-8f * sum; ++i) {
    term *= q * kInvSquares[i];
    sum += term;
  }
  return sum;
}

// ln I0(x). Beyond 12, where the series needs many terms and I0 soon overflows a float, its
// asymptotic expansion e^x / sqrt(2 pi x) (1 + 1/(8x) + 9/(128x^2) + 225/(3072x^3)), whose
// next term is below 3e-6 there. (pbrt-v4 adds 1/(16x) where ln(1 + 1/(8x)) belongs: its M_p
// is up to 0.5 % low where cos_i cos_o / v > 12, for beta_m below about 0.35, and then
// integrates to less than 1 while its sampling draws the exact lobe.)
double log_bessel_i0(double x) {
  if (x <= 12.0) return std::log(double(bessel_i0(float(x))));
  const double r = 1.0 / x;
  return x - 0.5 * std::log(2.0 * kPi * x) + std::log1p(r * (1.0 / 8.0 + r * (9.0 / 128.0 + r * (225.0 / 3072.0))));
}

// d'Eon et al.'s longitudinal lobe exp(-sin_i sin_o / v) I0(cos_i cos_o / v) / (2 v sinh(1/v)):
// its integral against cos theta_i over theta_i in [-pi/2, pi/2] is 1 for any theta_o. For
// v <= 0.1, sinh(1/v) and I0 overflow a float, so it is taken as the exponential of its
// logarithm, with ln sinh(1/v) = 1/v - ln 2 (to 2e-9 there), in double: the terms reach
// 1/v = 1e4 and cancel to order 1.
float longitudinal(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
  if (v <= 0.1f) {
    const double a = double(cos_i) * cos_o / v, b = double(sin_i) * sin_o / v;
    return float(std::exp(log_bessel_i0(a) - b - 1.0 / v + std::log(2.0) - std::log(2.0 * v)));
  }
  const float a = cos_i * cos_o / v, b = sin_i * sin_o / v;
  return std::exp(-b) * bessel_i0(a) / (std::sinh(1.f / v) * 2.f * v);
}

float logistic(float x, float s) {
  const float e = std::exp(-std::abs(x) / s);
  return e / (s * sqr(1.f + e));
}
float logistic_cdf(float x, float s) { return 1.f / (1.f + std::exp(-x / s)); }

// The inverse CDF of the logistic restricted to [-pi, pi]. u at either end of the range gives -s ln(inf) or -s ln(0):
// infinities, which the clamp turns into -pi and pi.
float sample_trimmed_logistic(float u, float s) {
  const float lo = logistic_cdf(-kPi, s), hi = logistic_cdf(kPi, s);
  u = lo + u * (hi - lo);
  return std::clamp(-s * std::log(1.f / u - 1.f), -kPi, kPi);
}

// Where lobe p leaves the fibre, in azimuth relative to wo: R is the mirror reflection,
// -2 gamma_o, and each further chord through the section adds pi + 2 gamma_t.
float exit_azimuth(int p, float gamma_o, float gamma_t) { return 2.f * p * gamma_t - 2.f * gamma_o + p * kPi; }

// N_p: the logistic about the exit azimuth, restricted to [-pi, pi] (the difference taken
// modulo 2 pi) and renormalised there by 1 / (its mass in [-pi, pi]).
float azimuthal(float phi, int p, float s, float inv_mass, float gamma_o, float gamma_t) {
  const float dphi = std::remainder(phi - exit_azimuth(p, gamma_o, gamma_t), 2.f * kPi);
  return logistic(dphi, s) * inv_mass;
}

}  // namespace

// What depends on wo only: its angles, the refracted ray's azimuthal angle gamma_t, each
// lobe's tilted longitudinal angle and attenuation A_p, and the lobe selection probabilities.
struct HairBxDF::Outgoing {
  float sin_o, cos_o, phi_o, gamma_t;
  std::array<float, kPMax + 1> sin_p, cos_p;
  std::array<SampledSpectrum, kPMax + 1> ap;
  std::array<float, kPMax + 1> ap_pdf;
  bool valid;  // some lobe carries light (the A_p do not all vanish)
};

HairBxDF::HairBxDF(float h, float eta, const SampledSpectrum& sigma_a, float beta_m, float beta_n, float alpha_deg)
    : h_(std::isfinite(h) ? std::clamp(h, -1.f, 1.f) : 0.f), eta_(eta) {
  gamma_o_ = std::asin(h_);
  cos_gamma_o_ = safe_sqrt(1.f - h_ * h_);
  // An infinite absorption (a reflectance of 0) stays the largest float: times a zero chord it
  // gives 0, not NaN.
  for (int i = 0; i < kSpectrumSamples; ++i)
    sigma_a_[i] = std::isnan(sigma_a[i]) ? 0.f : std::clamp(sigma_a[i], 0.f, FLT_MAX);
  const float bm = std::isfinite(beta_m) ? std::clamp(beta_m, 0.01f, 1.f) : 0.3f;
  const float bn = std::isfinite(beta_n) ? std::clamp(beta_n, 0.01f, 1.f) : 0.3f;
  // Chiang et al.'s fits of the lobe widths to the roughnesses (their equations 7 and 8):
  // TT is narrower and TRT wider than R; longer paths are given TRT's.
  v_[0] = sqr(0.726f * bm + 0.812f * bm * bm + 3.7f * std::pow(bm, 20.f));
  v_[1] = 0.25f * v_[0];
  v_[2] = 4.f * v_[0];
  v_[3] = v_[2];
  s_ = 0.626657069f * (0.265f * bn + 1.194f * bn * bn + 5.372f * std::pow(bn, 22.f));  // sqrt(pi/8) * fit
  inv_logistic_mass_ = 1.f / (logistic_cdf(kPi, s_) - logistic_cdf(-kPi, s_));
  // The cuticle's scales tilt R by -2 alpha, TT by alpha and TRT by 4 alpha.
  const float alpha = std::isfinite(alpha_deg) ? radians(alpha_deg) : 0.f;
  const float tilt[kPMax + 1] = {-2.f * alpha, alpha, 4.f * alpha, 0.f};
  for (int p = 0; p <= kPMax; ++p) {
    sin_tilt_[p] = std::sin(tilt[p]);
    cos_tilt_[p] = std::cos(tilt[p]);
  }
}

HairBxDF::Outgoing HairBxDF::outgoing(const Vec3& wo) const {
  Outgoing o;
  o.sin_o = std::clamp(wo.x, -1.f, 1.f);
  o.cos_o = safe_sqrt(1.f - o.sin_o * o.sin_o);
  o.phi_o = std::atan2(wo.z, wo.y);
  // The refracted ray in the fibre: its longitudinal angle by Snell's law, and its azimuthal
  // offset by Snell's law in the section with Bravais' modified index sqrt(eta^2 - sin^2) / cos.
  const float sin_t = o.sin_o / eta_, cos_t = safe_sqrt(1.f - sin_t * sin_t);
  const float d = safe_sqrt(eta_ * eta_ - o.sin_o * o.sin_o);
  // d = 0 only for eta <= 1 at grazing: no refracted ray, its sine taken at the limit 1.
  const float sin_gamma_t = d > 0.f ? std::clamp(h_ * o.cos_o / d, -1.f, 1.f) : std::copysign(1.f, h_);
  const float cos_gamma_t = safe_sqrt(1.f - sin_gamma_t * sin_gamma_t);
  o.gamma_t = std::asin(sin_gamma_t);
  // Transmittance of one chord (length 2 cos gamma_t / cos theta_t in radii). A chord of zero
  // length transmits everything even at infinite sigma_a; cos_t = 0 (eta < 1) none.
  const float chord = cos_t > 0.f ? 2.f * cos_gamma_t / cos_t : FLT_MAX;
  SampledSpectrum t;
  for (int i = 0; i < kSpectrumSamples; ++i)
    t[i] = chord == 0.f || sigma_a_[i] == 0.f ? 1.f : std::exp(-sigma_a_[i] * chord);
  // A_p: R reflects with Fresnel f at the entry; each further lobe crosses one more chord and
  // reflects once more inside; the last lobe sums the geometric series of all longer paths.
  const float fr = fresnel_dielectric(o.cos_o * cos_gamma_o_, eta_);
  o.ap[0] = SampledSpectrum(fr);
  o.ap[1] = sqr(1.f - fr) * t;
  o.ap[2] = o.ap[1] * t * fr;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float rest = 1.f - t[i] * fr;
    o.ap[3][i] = rest > 0.f ? o.ap[2][i] * fr * t[i] / rest : 0.f;
  }
  float sum = 0.f;
  for (int p = 0; p <= kPMax; ++p) sum += o.ap[p].average();
  o.valid = sum > 0.f && std::isfinite(sum);
  for (int p = 0; p <= kPMax; ++p) o.ap_pdf[p] = o.valid ? o.ap[p].average() / sum : 0.f;
  // The tilted lobe centres; a tilt past the pole folds back (|cos|), as in pbrt-v4.
  for (int p = 0; p <= kPMax; ++p) {
    o.sin_p[p] = o.sin_o * cos_tilt_[p] + o.cos_o * sin_tilt_[p];
    o.cos_p[p] = std::abs(o.cos_o * cos_tilt_[p] - o.sin_o * sin_tilt_[p]);
  }
  return o;
}

HairBxDF::Lobes HairBxDF::lobes(const Outgoing& o, const Vec3& wi) const {
  const float sin_i = std::clamp(wi.x, -1.f, 1.f), cos_i = safe_sqrt(1.f - sin_i * sin_i);
  const float phi = std::atan2(wi.z, wi.y) - o.phi_o;
  Lobes l;
  for (int p = 0; p < kPMax; ++p) {
    const float mn = longitudinal(cos_i, o.cos_p[p], sin_i, o.sin_p[p], v_[p]) *
                     azimuthal(phi, p, s_, inv_logistic_mass_, gamma_o_, o.gamma_t);
    l.f_cos += mn * o.ap[p];
    l.pdf += mn * o.ap_pdf[p];
  }
  const float m = longitudinal(cos_i, o.cos_p[kPMax], sin_i, o.sin_p[kPMax], v_[kPMax]) * kInv2Pi;
  l.f_cos += m * o.ap[kPMax];
  l.pdf += m * o.ap_pdf[kPMax];
  return l;
}

SampledSpectrum HairBxDF::f(const Vec3& wo, const Vec3& wi) const {
  if (wi.z == 0.f) return SampledSpectrum(0.f);
  const Outgoing o = outgoing(wo);
  return lobes(o, wi).f_cos / std::abs(wi.z);
}

float HairBxDF::pdf(const Vec3& wo, const Vec3& wi) const {
  const Outgoing o = outgoing(wo);
  return o.valid ? lobes(o, wi).pdf : 0.f;
}

std::optional<BSDFSample> HairBxDF::sample_f(const Vec3& wo, float uc, Vec2 u) const {
  const Outgoing o = outgoing(wo);
  if (!o.valid) return std::nullopt;
  // The lobe, in proportion to A_p; uc is then rescaled to [0, 1) for the azimuth.
  int p = 0;
  float below = 0.f;
  while (p < kPMax && uc >= below + o.ap_pdf[p]) below += o.ap_pdf[p++];
  while (p > 0 && !(o.ap_pdf[p] > 0.f)) below -= o.ap_pdf[--p];  // rounding past the last lobe with light
  uc = std::min((uc - below) / o.ap_pdf[p], kOneMinusEpsilon);
  // M_p by inversion (d'Eon et al.): the cosine of the angle to the lobe's centre, then a
  // uniform angle about it; the 1e-5 floor keeps the logarithm finite.
  const float cos_theta = 1.f + v_[p] * std::log(std::max(u.x, 1e-5f) + (1.f - u.x) * std::exp(-2.f / v_[p]));
  const float sin_theta = safe_sqrt(1.f - cos_theta * cos_theta);
  const float sin_i =
      std::clamp(-cos_theta * o.sin_p[p] + sin_theta * std::cos(2.f * kPi * u.y) * o.cos_p[p], -1.f, 1.f);
  const float cos_i = safe_sqrt(1.f - sin_i * sin_i);
  // N_p: the logistic about the lobe's exit azimuth; the last lobe uniform.
  const float dphi =
      p < kPMax ? exit_azimuth(p, gamma_o_, o.gamma_t) + sample_trimmed_logistic(uc, s_) : 2.f * kPi * uc;
  const float phi_i = o.phi_o + dphi;
  BSDFSample s;
  s.wi = Vec3(sin_i, cos_i * std::cos(phi_i), cos_i * std::sin(phi_i));
  if (s.wi.z == 0.f) return std::nullopt;
  const Lobes l = lobes(o, s.wi);
  s.f = l.f_cos / std::abs(s.wi.z);
  s.pdf = l.pdf;
  s.flags = kGlossy | (wo.z * s.wi.z > 0.f ? kReflection : kTransmission);
  if (!(s.pdf > 0.f) || !is_finite(s.f)) return std::nullopt;
  return s;
}

RGB HairBxDF::sigma_a_from_concentration(float eumelanin, float pheomelanin) {
  return eumelanin * RGB(0.419f, 0.697f, 1.37f) + pheomelanin * RGB(0.187f, 0.4f, 1.05f);
}

SampledSpectrum HairBxDF::sigma_a_from_reflectance(const SampledSpectrum& c, float beta_n) {
  const float b = beta_n;
  const float denom =
      5.969f - 0.215f * b + 2.532f * b * b - 10.73f * b * b * b + 5.574f * b * b * b * b + 0.245f * b * b * b * b * b;
  SampledSpectrum sigma_a;
  for (int i = 0; i < kSpectrumSamples; ++i) sigma_a[i] = sqr(std::log(c[i]) / denom);
  return sigma_a;
}

}  // namespace eyetrace
