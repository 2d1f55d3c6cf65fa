#include "materials/tabulated_bssrdf.h"

#include <cmath>

#include "core/catmull_rom.h"
#include "core/constants.h"
#include "materials/local_bsdf.h"
#include "materials/normalized_fresnel_bxdf.h"

namespace eyetrace {

TabulatedBSSRDF::TabulatedBSSRDF(const Vec3& po, const Vec3& ns, float eta, const SampledSpectrum& sigma_a,
                                 const SampledSpectrum& sigma_s, const BSSRDFTable* table)
    : po_(po), frame_(ns), eta_(eta), sigma_t_(sigma_a + sigma_s), table_(table) {
  rho_ = safe_div(sigma_s, sigma_t_);
}

bool TabulatedBSSRDF::profile_at(int i, float r, float* sr, float* rho_eff) const {
  const float r_optical = r * sigma_t_[i];
  int rho_offset, radius_offset;
  float rho_w[4], radius_w[4];
  if (!catmull_rom_weights(table_->rho_samples, rho_[i], &rho_offset, rho_w) ||
      !catmull_rom_weights(table_->radius_samples, r_optical, &radius_offset, radius_w))
    return false;
  float s = 0.f, re = 0.f;
  for (int j = 0; j < 4; ++j) {
    if (rho_w[j] == 0.f) continue;
    re += table_->rho_eff[rho_offset + j] * rho_w[j];
    for (int k = 0; k < 4; ++k)
      if (radius_w[k] != 0.f) s += table_->eval_profile(rho_offset + j, radius_offset + k) * rho_w[j] * radius_w[k];
  }
  // The table holds 2 pi r S(r) (the radial marginal); cancel that factor.
  if (r_optical != 0.f) s /= 2.f * kPi * r_optical;
  *sr = s;
  *rho_eff = re;
  return true;
}

SampledSpectrum TabulatedBSSRDF::sr(float r) const {
  SampledSpectrum out(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float s, re;
    // Optical units to scene units: S scales with sigma_t^2 (an area density).
    if (profile_at(i, r, &s, &re)) out[i] = std::max(0.f, s * sigma_t_[i] * sigma_t_[i]);
  }
  return out;
}

std::optional<float> TabulatedBSSRDF::sample_sr(float u) const {
  if (!(sigma_t_[0] > 0.f)) return std::nullopt;
  return sample_catmull_rom_2d(table_->rho_samples, table_->radius_samples, table_->profile, table_->profile_cdf,
                               rho_[0], u) /
         sigma_t_[0];
}

SampledSpectrum TabulatedBSSRDF::pdf_sr(float r) const {
  SampledSpectrum out(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float s, re;
    if (profile_at(i, r, &s, &re) && re > 0.f) out[i] = std::max(0.f, s * sigma_t_[i] * sigma_t_[i] / re);
  }
  return out;
}

std::optional<BSSRDFProbeSegment> TabulatedBSSRDF::sample_sp(float u1, Vec2 u2) const {
  // The probe runs along `axis`; the radius lies in the plane of `a` and `b` (pbrt-v4: the
  // two tangents with probability 1/4 each, the normal with 1/2).
  Vec3 a = frame_.s, b = frame_.t, axis = frame_.n;
  if (u1 < 0.25f) {
    a = frame_.t, b = frame_.n, axis = frame_.s;
  } else if (u1 < 0.5f) {
    a = frame_.n, b = frame_.s, axis = frame_.t;
  }
  const std::optional<float> r = sample_sr(u2.x);
  if (!r) return std::nullopt;
  const float phi = 2.f * kPi * u2.y;
  // The profile's extent: beyond the 99.9th percentile radius, nothing is probed.
  const std::optional<float> r_max = sample_sr(0.999f);
  if (!r_max || !(*r < *r_max) || !std::isfinite(*r_max)) return std::nullopt;
  const float l = 2.f * std::sqrt(*r_max * *r_max - *r * *r);
  const Vec3 start = po_ + *r * (a * std::cos(phi) + b * std::sin(phi)) - 0.5f * l * axis;
  return BSSRDFProbeSegment{start, start + l * axis};
}

SampledSpectrum TabulatedBSSRDF::pdf_sp(const Vec3& pi, const Vec3& ni) const {
  const Vec3 d = frame_.to_local(pi - po_), n = frame_.to_local(ni);
  // Radius of pi as seen along each axis (s, t, n), and the axes' probabilities.
  const float r_proj[3] = {std::sqrt(d.y * d.y + d.z * d.z), std::sqrt(d.z * d.z + d.x * d.x),
                           std::sqrt(d.x * d.x + d.y * d.y)};
  const float axis_prob[3] = {0.25f, 0.25f, 0.5f};
  SampledSpectrum pdf(0.f);
  for (int axis = 0; axis < 3; ++axis) pdf += pdf_sr(r_proj[axis]) * (std::abs(n[axis]) * axis_prob[axis]);
  return pdf;
}

BSSRDFSample TabulatedBSSRDF::probe_intersection_to_sample(const SurfaceInteraction& exit, ScratchBuffer& arena) const {
  BSSRDFSample s;
  s.sp = sr(glm::length(exit.p - po_));
  s.pdf = pdf_sp(exit.p, exit.n);
  s.sw = make_local_bsdf(arena, exit, NormalizedFresnelBxDF(eta_));
  return s;
}

}  // namespace eyetrace
