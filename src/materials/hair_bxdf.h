// The hair fibre BSDF of Chiang, Bitterli, Tappan & Burley, "A Practical and Controllable Hair
// and Fur Model for Production Path Tracing" (2016), as pbrt-v4 (and pbrt-v3's hair chapter)
// define it. The fibre is a dielectric cylinder (index eta) that absorbs sigma_a per unit of
// its radius; a ray met it at offset h in [-1, 1] across its width.
//
// Local frame: +x along the fibre (dpdu), +z the shading normal. theta is the angle of a
// direction out of the plane normal to the fibre (sin theta = w.x), phi its azimuth about the
// fibre, measured from +y (atan2(w.z, w.y)). Scattering is the sum of lobes p = 0 (R: reflected
// at the surface), 1 (TT: through), 2 (TRT: one internal reflection) and one lobe p = 3 for all
// longer paths, each M_p(theta_i) A_p N_p(phi):
//  - M_p, longitudinal: d'Eon et al. 2011's lobe of variance v_p (from beta_m), about the
//    mirror direction tilted by the cuticle scales' angle alpha (-2 alpha, alpha, 4 alpha, 0);
//  - A_p, attenuation: Fresnel reflection at the surface and absorption along each chord;
//  - N_p, azimuthal: a logistic of scale s (from beta_n) about the exit azimuth of a ray through
//    a circular section at h; the last lobe is uniform in azimuth.
// Each M_p and N_p is normalised, so f |wi.z| integrates over the sphere to sum_p A_p: exactly
// 1 for a fibre that does not absorb. As in pbrt-v4, f is that sum divided by |wi.z|, so that
// the integrator's cosine factor gives the lobes back. Sampling picks a lobe in proportion to
// its A_p (averaged over the wavelengths) and then samples M_p and N_p exactly.
#pragma once
#include <array>
#include <optional>

#include "core/bsdf.h"
#include "core/spectrum.h"

namespace eyetrace {

class HairBxDF {
 public:
  static constexpr int kPMax = 3;  // lobes 0..2 explicitly, lobe 3 for everything longer

  // beta_m and beta_n are clamped to [0.01, 1] (pbrt-v4's material does so; 0 has no lobe
  // width), h to [-1, 1], sigma_a to non-negative; alpha is in degrees; eta must be positive.
  HairBxDF(float h, float eta, const SampledSpectrum& sigma_a, float beta_m, float beta_n, float alpha_deg);

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const;
  std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2 u) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // Light leaves a fibre on every side; pbrt-v4 says GlossyReflection, which means the same to
  // its integrator and ours (glossy: lights are sampled).
  unsigned flags() const { return kReflection | kTransmission | kGlossy; }

  // Absorption (per unit radius) of the two melanins at the given concentrations: Chiang et
  // al.'s sRGB coefficients (0.419, 0.697, 1.37) and (0.187, 0.4, 1.05), as pbrt-v4, to be
  // read as an unbounded RGB spectrum.
  static RGB sigma_a_from_concentration(float eumelanin, float pheomelanin);
  // Chiang et al.'s fit: the sigma_a whose multiply scattered colour is c (in [0, 1]), given
  // the azimuthal roughness beta_n: (ln c / (5.969 - 0.215 b + 2.532 b^2 - 10.73 b^3 + 5.574 b^4
  // + 0.245 b^5))^2.
  static SampledSpectrum sigma_a_from_reflectance(const SampledSpectrum& c, float beta_n);

 private:
  struct Outgoing;
  struct Lobes {
    SampledSpectrum f_cos{0.f};  // sum of M_p A_p N_p: f |wi.z|
    float pdf = 0.f;
  };
  Outgoing outgoing(const Vec3& wo) const;
  Lobes lobes(const Outgoing& o, const Vec3& wi) const;

  float h_, gamma_o_, cos_gamma_o_, eta_;
  SampledSpectrum sigma_a_;
  std::array<float, kPMax + 1> v_;                    // longitudinal variances
  float s_, inv_logistic_mass_;                       // azimuthal logistic scale; 1 / its mass in [-pi, pi]
  std::array<float, kPMax + 1> sin_tilt_, cos_tilt_;  // each lobe's scale tilt
};

}  // namespace eyetrace
