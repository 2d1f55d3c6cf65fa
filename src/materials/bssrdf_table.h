// The photon beam diffusion (PBD) profile of a semi-infinite homogeneous medium below a smooth
// dielectric boundary (Habel, Christensen and Jarosz 2013; d'Eon's quantized-diffusion dipole
// with Grosjean's diffusion coefficient), tabulated over single-scattering albedo rho and optical
// radius r as pbrt-v4's BSSRDFTable: profile(rho, r) = 2 pi r (S_ss + S_ms) for a medium of
// sigma_t = 1, its integral over r (rho_eff, the total diffuse reflectance) and per-rho CDFs.
// Computed once per material (pbrt-v4: 100 albedos x 64 radii).
#pragma once
#include <span>
#include <vector>

#include "core/sampled_spectrum.h"

namespace eyetrace {

// Angular moments of the dielectric Fresnel reflectance, 2 int_0^1 Fr(mu, eta) mu^i dmu for
// i = 1, 2, as pbrt-v4's polynomial fits.
float fresnel_moment1(float eta);
float fresnel_moment2(float eta);

// Multiple-scattering radial exitance at distance r of a beam entering along the normal
// (PBD, 100 depth samples), and its single-scattering part (100 samples below the critical
// angle's depth), for coefficients per unit length.
float beam_diffusion_ms(float sigma_s, float sigma_a, float g, float eta, float r);
float beam_diffusion_ss(float sigma_s, float sigma_a, float g, float eta, float r);

struct BSSRDFTable {
  std::vector<float> rho_samples, radius_samples;
  std::vector<float> profile;      // [rho][radius], 2 pi r S(r) at sigma_t = 1
  std::vector<float> rho_eff;      // [rho]: integral of the profile over r
  std::vector<float> profile_cdf;  // [rho][radius]: running integral

  float eval_profile(int rho_index, int radius_index) const {
    return profile[size_t(rho_index) * radius_samples.size() + size_t(radius_index)];
  }
  std::span<const float> profile_row(int rho_index) const {
    return {profile.data() + size_t(rho_index) * radius_samples.size(), radius_samples.size()};
  }
};

// pbrt-v4's ComputeBeamDiffusionBSSRDF: radii 0, 2.5e-3, then x1.2 each; albedos
// (1 - exp(-8 i / (n - 1))) / (1 - exp(-8)).
BSSRDFTable compute_beam_diffusion_table(float g, float eta, int n_rho = 100, int n_radius = 64);

// The coefficients whose effective albedo is `rho_eff` and mean free path `mfp` (per
// wavelength: rho = rho_eff inverted through the table, sigma_s = rho / mfp, sigma_a = (1 - rho)
// / mfp), pbrt-v4's SubsurfaceFromDiffuse.
void subsurface_from_diffuse(const BSSRDFTable& t, const SampledSpectrum& rho_eff, const SampledSpectrum& mfp,
                             SampledSpectrum* sigma_a, SampledSpectrum* sigma_s);

}  // namespace eyetrace
