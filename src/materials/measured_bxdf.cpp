#include "materials/measured_bxdf.h"

#include "materials/bxdf_util.h"
#include "materials/fresnel.h"

namespace eyetrace {

namespace {

// The RGL parameterization of angles on the unit square (theta: square root, denser near
// the pole where glossy lobes are; phi: [-pi, pi] onto [0, 1]).
float theta_to_u(float theta) { return std::sqrt(theta * (2.f / kPi)); }
float phi_to_u(float phi) { return phi * kInv2Pi + 0.5f; }
float u_to_theta(float u) { return sqr(u) * (kPi / 2.f); }
float u_to_phi(float u) { return (2.f * u - 1.f) * kPi; }

float spherical_theta(const Vec3& w) { return std::acos(std::clamp(w.z, -1.f, 1.f)); }
float spherical_phi(const Vec3& w) { return std::atan2(w.y, w.x); }

// The solid angle a unit-square cell of the normal's (u_theta, u_phi) covers, per unit area:
// d omega = sin theta d theta d phi = 2 pi^2 u sin theta du_theta du_phi, floored as in pbrt-v4
// so that the pole (u = 0) does not divide by zero.
float square_to_solid_angle(float u_theta, float sin_theta) {
  return std::max(2.f * sqr(kPi) * u_theta * sin_theta, 1e-6f);
}

bool finite_point(const Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The half vector of a reflection pair on the upper side; false when it does not exist.
bool half_vector(Vec3* wo, Vec3* wi, Vec3* wm) {
  if (!same_hemisphere(*wo, *wi)) return false;
  if (wo->z < 0.f) {
    *wo = -*wo;
    *wi = -*wi;
  }
  Vec3 h = *wi + *wo;
  const float len2 = glm::dot(h, h);
  if (!(len2 > 0.f)) return false;
  *wm = h / std::sqrt(len2);
  return true;
}

}  // namespace

SampledSpectrum MeasuredBxDF::spectrum(Vec2 u, float phi_o, float theta_o) const {
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float param[3] = {phi_o, theta_o, lambda_[i]};
    s[i] = std::max(0.f, brdf_->spectra.evaluate(u, param));
  }
  return s;
}

SampledSpectrum MeasuredBxDF::f(Vec3 wo, Vec3 wi) const {
  Vec3 wm;
  if (!half_vector(&wo, &wi, &wm)) return SampledSpectrum(0.f);
  const float theta_o = spherical_theta(wo), phi_o = spherical_phi(wo);
  const float theta_m = spherical_theta(wm), phi_m = spherical_phi(wm);
  const Vec2 u_wo(theta_to_u(theta_o), phi_to_u(phi_o));
  Vec2 u_wm(theta_to_u(theta_m), phi_to_u(brdf_->isotropic ? phi_m - phi_o : phi_m));
  u_wm.y -= std::floor(u_wm.y);

  const float param[2] = {phi_o, theta_o};
  const PiecewiseLinear2D::Sample ui = brdf_->vndf.invert(u_wm, param);
  // A normal the visible-normal table gives no density has no inverse (pbrt-v4 would go on
  // with NaN): it reflects nothing.
  if (!finite_point(ui.p)) return SampledSpectrum(0.f);
  const float denom = 4.f * brdf_->sigma.evaluate(u_wo, nullptr) * wi.z;
  const SampledSpectrum fr = spectrum(ui.p, phi_o, theta_o) * (brdf_->ndf.evaluate(u_wm, nullptr) / denom);
  return denom > 0.f && is_finite(fr) ? fr : SampledSpectrum(0.f);
}

std::optional<BSDFSample> MeasuredBxDF::sample_f(Vec3 wo, float /*uc*/, Vec2 u) const {
  const bool flip = wo.z <= 0.f;
  if (flip) wo = -wo;
  const float theta_o = spherical_theta(wo), phi_o = spherical_phi(wo);
  const float param[2] = {phi_o, theta_o};

  // The luminance warp picks the sample-square point, the visible-normal warp the normal.
  const PiecewiseLinear2D::Sample lum = brdf_->luminance.sample(u, param);
  const PiecewiseLinear2D::Sample vn = brdf_->vndf.sample(lum.p, param);
  const Vec2 u_wm = vn.p;
  float phi_m = u_to_phi(u_wm.y);
  const float theta_m = u_to_theta(u_wm.x);
  if (brdf_->isotropic) phi_m += phi_o;
  const float sin_m = std::sin(theta_m), cos_m = std::cos(theta_m);
  const Vec3 wm(sin_m * std::cos(phi_m), sin_m * std::sin(phi_m), cos_m);
  BSDFSample s;
  s.wi = reflect(wo, wm);
  if (!(s.wi.z > 0.f)) return std::nullopt;  // the mirrored direction is below the surface

  const Vec2 u_wo(theta_to_u(theta_o), phi_to_u(phi_o));
  const float denom = 4.f * brdf_->sigma.evaluate(u_wo, nullptr) * s.wi.z;
  s.f = spectrum(lum.p, phi_o, theta_o) * (brdf_->ndf.evaluate(u_wm, nullptr) / denom);
  s.pdf = vn.pdf * lum.pdf / (4.f * glm::dot(wo, wm) * square_to_solid_angle(u_wm.x, sin_m));
  s.flags = kReflection | kGlossy;
  if (!(denom > 0.f) || !std::isfinite(s.pdf) || !(s.pdf > 0.f) || !is_finite(s.f)) return std::nullopt;
  if (flip) s.wi = -s.wi;
  return s;
}

float MeasuredBxDF::pdf(Vec3 wo, Vec3 wi) const {
  Vec3 wm;
  if (!half_vector(&wo, &wi, &wm)) return 0.f;
  const float theta_o = spherical_theta(wo), phi_o = spherical_phi(wo);
  const float theta_m = spherical_theta(wm), phi_m = spherical_phi(wm);
  Vec2 u_wm(theta_to_u(theta_m), phi_to_u(brdf_->isotropic ? phi_m - phi_o : phi_m));
  u_wm.y -= std::floor(u_wm.y);

  const float param[2] = {phi_o, theta_o};
  const PiecewiseLinear2D::Sample ui = brdf_->vndf.invert(u_wm, param);
  if (!finite_point(ui.p)) return 0.f;
  const float lum_pdf = brdf_->luminance.evaluate(ui.p, param);
  const float sin_m = std::sqrt(sqr(wm.x) + sqr(wm.y));
  const float pdf = ui.pdf * lum_pdf / (4.f * glm::dot(wo, wm) * square_to_solid_angle(u_wm.x, sin_m));
  return std::isfinite(pdf) && pdf > 0.f ? pdf : 0.f;
}

}  // namespace eyetrace
