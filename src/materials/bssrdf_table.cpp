#include "materials/bssrdf_table.h"

#include <algorithm>
#include <cmath>

#include "core/catmull_rom.h"
#include "core/constants.h"
#include "core/henyey_greenstein.h"
#include "core/math.h"
#include "materials/fresnel.h"

namespace eyetrace {

namespace {

constexpr float kInv4Pi = 0.25f * kInvPi;

// Depth of the i-th of n stratified samples of an exponential of rate a (pbrt-v4's
// SampleExponential at (i + 0.5) / n).
float exponential_sample(int i, int n, float a) { return -std::log(1.f - (float(i) + 0.5f) / float(n)) / a; }

}  // namespace

float fresnel_moment1(float eta) {
  const float e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
  if (eta < 1.f) return 0.45966f - 1.73965f * eta + 3.37668f * e2 - 3.904945f * e3 + 2.49277f * e4 - 0.68441f * e5;
  return -4.61686f + 11.1136f * eta - 10.4646f * e2 + 5.11455f * e3 - 1.27198f * e4 + 0.12746f * e5;
}

float fresnel_moment2(float eta) {
  const float e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
  if (eta < 1.f) return 0.27614f - 0.87350f * eta + 1.12077f * e2 - 0.65095f * e3 + 0.07883f * e4 + 0.04860f * e5;
  const float r = 1.f / eta, r2 = r * r, r3 = r2 * r;
  return -547.033f + 45.3087f * r3 - 218.725f * r2 + 458.843f * r + 404.557f * eta - 189.519f * e2 + 54.9327f * e3 -
         9.00603f * e4 + 0.63942f * e5;
}

float beam_diffusion_ms(float sigma_s, float sigma_a, float g, float eta, float r) {
  constexpr int kSamples = 100;
  // Reduced coefficients (similarity theory) and Grosjean's non-classical diffusion coefficient.
  const float sigmap_s = sigma_s * (1.f - g), sigmap_t = sigma_a + sigmap_s, rhop = sigmap_s / sigmap_t;
  const float D_g = (2.f * sigma_a + sigmap_s) / (3.f * sigmap_t * sigmap_t);
  const float sigma_tr = safe_sqrt(sigma_a / D_g);
  // Partial-current boundary condition: the extrapolation distance and the exitance weights of
  // fluence and flux.
  const float fm1 = fresnel_moment1(eta), fm2 = fresnel_moment2(eta);
  const float ze = -2.f * D_g * (1.f + 3.f * fm2) / (1.f - 2.f * fm1);
  const float c_phi = 0.25f * (1.f - 2.f * fm1), c_e = 0.5f * (1.f - 3.f * fm2);
  float Ed = 0.f;
  for (int i = 0; i < kSamples; ++i) {
    // A real source at depth zr along the beam, its image at zv mirrored about the
    // extrapolated boundary.
    const float zr = exponential_sample(i, kSamples, sigmap_t), zv = -zr + 2.f * ze;
    const float dr = std::sqrt(r * r + zr * zr), dv = std::sqrt(r * r + zv * zv);
    const float er = std::exp(-sigma_tr * dr), ev = std::exp(-sigma_tr * dv);
    const float phi_d = kInv4Pi / D_g * (er / dr - ev / dv);
    const float ed_n =
        kInv4Pi * (zr * (1.f + sigma_tr * dr) * er / (dr * dr * dr) - zv * (1.f + sigma_tr * dv) * ev / (dv * dv * dv));
    const float E = phi_d * c_phi + ed_n * c_e;
    // Habel et al.'s correction for sources close to the exit point.
    const float kappa = 1.f - std::exp(-2.f * sigmap_t * (dr + zr));
    Ed += kappa * rhop * rhop * E;
  }
  return Ed / kSamples;
}

float beam_diffusion_ss(float sigma_s, float sigma_a, float g, float eta, float r) {
  constexpr int kSamples = 100;
  const float sigma_t = sigma_a + sigma_s, rho = sigma_s / sigma_t;
  // Below this depth the path to the exit point would leave beyond the critical angle.
  const float t_crit = r * safe_sqrt(eta * eta - 1.f);
  // pbrt-v4's HenyeyGreenstein clamps g to [-0.99, 0.99], where the lobe is still resolvable.
  g = std::clamp(g, -0.99f, 0.99f);
  float Ess = 0.f;
  for (int i = 0; i < kSamples; ++i) {
    const float ti = t_crit + exponential_sample(i, kSamples, sigma_t);
    const float d = std::sqrt(r * r + ti * ti), cos_o = ti / d;
    // pbrt-v4's HenyeyGreenstein(cos_o, g) measures the angle between the two directions
    // pointing away from the scattering point; eyetrace's takes the travel direction: -cos_o.
    Ess += rho * std::exp(-sigma_t * (d + t_crit)) / (d * d) * henyey_greenstein(-cos_o, g) *
           (1.f - fresnel_dielectric(-cos_o, eta)) * std::abs(cos_o);
  }
  return Ess / kSamples;
}

BSSRDFTable compute_beam_diffusion_table(float g, float eta, int n_rho, int n_radius) {
  BSSRDFTable t;
  t.rho_samples.resize(size_t(n_rho));
  t.radius_samples.resize(size_t(n_radius));
  t.profile.resize(size_t(n_rho) * size_t(n_radius));
  t.profile_cdf.resize(t.profile.size());
  t.rho_eff.resize(size_t(n_rho));
  t.radius_samples[0] = 0.f;
  t.radius_samples[1] = 2.5e-3f;
  for (int i = 2; i < n_radius; ++i) t.radius_samples[i] = t.radius_samples[i - 1] * 1.2f;
  for (int i = 0; i < n_rho; ++i)
    t.rho_samples[i] = (1.f - std::exp(-8.f * float(i) / float(n_rho - 1))) / (1.f - std::exp(-8.f));
  for (int i = 0; i < n_rho; ++i) {
    const float rho = t.rho_samples[i];
    for (int j = 0; j < n_radius; ++j) {
      const float r = t.radius_samples[j];
      t.profile[size_t(i) * n_radius + j] =
          2.f * kPi * r * (beam_diffusion_ss(rho, 1.f - rho, g, eta, r) + beam_diffusion_ms(rho, 1.f - rho, g, eta, r));
    }
    t.rho_eff[i] = integrate_catmull_rom(t.radius_samples, t.profile_row(i),
                                         std::span<float>(t.profile_cdf.data() + size_t(i) * n_radius, n_radius));
  }
  return t;
}

void subsurface_from_diffuse(const BSSRDFTable& t, const SampledSpectrum& rho_eff, const SampledSpectrum& mfp,
                             SampledSpectrum* sigma_a, SampledSpectrum* sigma_s) {
  for (int c = 0; c < kSpectrumSamples; ++c) {
    const float rho = invert_catmull_rom(t.rho_samples, t.rho_eff, rho_eff[c]);
    (*sigma_s)[c] = rho / mfp[c];
    (*sigma_a)[c] = (1.f - rho) / mfp[c];
  }
}

}  // namespace eyetrace
