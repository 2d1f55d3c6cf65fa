#include "integrators/volpath_integrator.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/henyey_greenstein.h"
#include "core/material.h"
#include "core/medium.h"
#include "core/sampling.h"
#include "integrators/subsurface_exit.h"
#include "render/scene.h"

namespace eyetrace {

namespace {

// Interface crossings do not count as bounces; bound them so a degenerate scene cannot loop.
constexpr int kMaxCrossings = 256;

// The average over the wavelengths the sample still carries: with the secondary wavelengths
// terminated (a dispersive surface, the eye) the path is the hero's alone, sampled by it, and
// its single-wavelength estimate needs no spectral MIS.
float carried_average(const SampledSpectrum& r, const SampledWavelengths& lambda) {
  return lambda.secondary_terminated() ? r[0] : r.average();
}

// exp(-sigma_t d) per wavelength; a wavelength the medium does not attenuate (sigma_t 0)
// keeps 1 even over an infinite distance (0 * inf would be NaN).
SampledSpectrum beer_lambert(const SampledSpectrum& sigma_t, float d) {
  SampledSpectrum T;
  for (int i = 0; i < kSpectrumSamples; ++i) T[i] = sigma_t[i] > 0.f ? std::exp(-sigma_t[i] * d) : 1.f;
  return T;
}

Ray unit_ray(Ray r) {
  const float len = glm::length(r.d);
  r.d /= len;
  r.tmax *= len;
  return r;
}

}  // namespace

VolPathIntegrator::VolPathIntegrator(const Scene& scene, int max_depth, float rr_threshold)
    : Integrator(scene), max_depth_(max_depth), rr_threshold_(rr_threshold), lights_(scene.lights()) {}

std::string VolPathIntegrator::to_string() const {
  return fmt::format("volpath integrator (participating media): maxdepth {}, {} light(s), power light sampling",
                     max_depth_, scene_.lights().size());
}

SampledSpectrum VolPathIntegrator::transmittance(Ray ray, const Medium* medium, const Vec3& p_to, const Vec3& err_to,
                                                 const Vec3& n_to, const SampledWavelengths& lambda,
                                                 RayTally& tally) const {
  SampledSpectrum T(1.f);
  for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
    SurfaceInteraction si;
    ++tally.rays;
    ++tally.shadow_rays;
    const bool hit = scene_.intersect(ray, &si);
    if (hit && si.material) return SampledSpectrum(0.f);  // blocked by a surface
    if (medium) {
      const MediumProperties mp = medium->properties(lambda);
      T *= beer_lambert(mp.sigma_a + mp.sigma_s, (hit ? si.t : ray.tmax) * glm::length(ray.d));
    }
    if (!hit || is_black(T)) return T;
    if (si.medium_interface) medium = si.medium_interface->towards(ray.d, si.n);
    ray = spawn_ray_to(si, p_to, err_to, n_to);
  }
  return SampledSpectrum(0.f);
}

// The MIS weights of next-event estimation. With the shadow ray's transmittance T computed
// exactly (not sampled), the light strategy's density of a path, for wavelength j, is
// p_path_j * p_light (the light's solid-angle density times its selection probability: no T,
// the segment is not sampled), while the scatter strategy (phase or BSDF direction, then
// free-flight sampling that must pass the whole segment) has p_path_j * p_scatter * T_j. The
// path was sampled by the hero wavelength: r_p = p_path_j / p_path_hero. Single-sample MIS
// over both strategies and all wavelengths (balance heuristic) gives the light strategy
//   beta f T L / avg_j(r_p_j (p_light + p_scatter T_j))
// (pbrt-v4's form with r_l = r_p p_light and r_u = r_p p_scatter T). Its counterpart, in
// radiance(): after a scatter r_l = r_u / p_scatter, and a segment survived multiplies
// r_u by T_j / T_hero (the scatter strategy pays for survival) and r_l by 1 / T_hero only (the
// light strategy does not), so emission found adds beta Le / avg(r_u + r_l p_light).
// Delta lights have no scatter strategy: beta f T L / avg(r_p p_light).
SampledSpectrum VolPathIntegrator::sample_light(const Scatterer& at, const SampledSpectrum& beta,
                                                const SampledSpectrum& r_p, const SampledWavelengths& lambda,
                                                Sampler& sampler, RayTally& tally) const {
  const float u_light = sampler.get_1d();
  const Vec2 u = sampler.get_2d();
  auto skip = [&] {
    ++tally.shadow_rays_skipped;
    return SampledSpectrum(0.f);
  };
  float pmf = 0.f;
  const Light* light = lights_.sample(u_light, &pmf);
  if (!light || pmf == 0.f) return skip();
  std::optional<LightLiSample> ls = light->sample_li(LightSampleContext{at.p, at.n}, u, lambda);
  if (!ls || ls->pdf <= 0.f || is_black(ls->L)) return skip();
  SampledSpectrum f_hat;
  float scatter_pdf;
  const Medium* medium = at.medium;
  if (at.bsdf) {
    f_hat = at.bsdf->f(at.si->wo, ls->wi) * std::abs(glm::dot(ls->wi, at.si->ns));
    scatter_pdf = at.bsdf->pdf(at.si->wo, ls->wi);
    if (at.si->medium_interface) medium = at.si->medium_interface->towards(ls->wi, at.n);
  } else {
    scatter_pdf = henyey_greenstein(glm::dot(at.d_in, ls->wi), at.g);
    f_hat = SampledSpectrum(scatter_pdf);
  }
  if (is_black(f_hat)) return skip();
  const Ray shadow = spawn_ray_to(at.p, at.p_error, at.n, at.time, ls->p_light, ls->p_light_error, ls->n_light);
  const SampledSpectrum T = transmittance(shadow, medium, ls->p_light, ls->p_light_error, ls->n_light, lambda, tally);
  if (is_black(T)) return SampledSpectrum(0.f);
  const float light_pdf = pmf * ls->pdf;
  const SampledSpectrum r_light = r_p * light_pdf;
  if (light->is_delta()) return beta * f_hat * T * ls->L / carried_average(r_light, lambda);
  return beta * f_hat * T * ls->L / carried_average(r_light + r_p * T * scatter_pdf, lambda);
}

bool VolPathIntegrator::continue_from_subsurface_exit(const SurfaceInteraction& entry, const BSSRDF& bssrdf,
                                                      SampledWavelengths& lambda, Sampler& sampler,
                                                      ScratchBuffer& arena, RayTally& tally, SampledSpectrum& beta,
                                                      SampledSpectrum& r_u, SampledSpectrum& r_l, SampledSpectrum& L,
                                                      Ray& ray, const Medium*& medium,
                                                      LightSampleContext& prev_ctx) const {
  const std::optional<SubsurfaceExit> exit =
      sample_subsurface_exit(scene_, bssrdf, entry, lambda, sampler, arena, tally);
  if (!exit) return false;
  // The hero's density weighs the throughput; r_u carries every wavelength's (pbrt-v4).
  beta *= exit->sp / exit->pdf[0];
  r_u *= exit->pdf / exit->pdf[0];
  // The exit is a surface point outside the entry's medium: light there as at any surface.
  Scatterer at;
  at.p = exit->si.p;
  at.p_error = exit->si.p_error;
  at.n = exit->si.n;
  at.time = exit->si.time;
  at.si = &exit->si;
  at.bsdf = exit->sw;
  at.medium = medium;
  if (!lights_.empty())
    L += sample_light(at, beta, r_u, lambda, sampler, tally);
  else
    ++tally.shadow_rays_skipped;
  const float uc = sampler.get_1d();
  const std::optional<BSDFSample> ws = exit->sw->sample_f(exit->si.wo, uc, sampler.get_2d());
  if (!ws || !(ws->pdf > 0.f) || is_black(ws->f)) return false;
  beta *= ws->f * std::abs(glm::dot(ws->wi, exit->si.ns)) / ws->pdf;
  r_l = r_u / ws->pdf;
  prev_ctx = LightSampleContext{exit->si.p, exit->si.n};
  if (exit->si.medium_interface) medium = exit->si.medium_interface->towards(ws->wi, exit->si.n);
  ray = unit_ray(spawn_ray(exit->si, ws->wi));
  return is_finite(beta) && is_finite(r_u);
}

SampledSpectrum VolPathIntegrator::radiance(const Ray& camera_ray, SampledWavelengths& lambda, Sampler& sampler,
                                            ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible) const {
  SampledSpectrum L(0.f), beta(1.f), r_u(1.f), r_l(1.f);
  Ray ray = unit_ray(camera_ray);
  const Medium* medium = scene_.camera_medium();
  bool specular_bounce = false;
  LightSampleContext prev_ctx;
  int depth = 0, crossings = 0;
  // Emission reached by the sampled path, MIS-weighted against light sampling.
  auto add_emission = [&](const Light* light, const SampledSpectrum& Le, const SurfaceInteraction* at) {
    if (is_black(Le)) return;
    if (depth == 0 || specular_bounce) {
      L += beta * Le / carried_average(r_u, lambda);
      return;
    }
    const float light_pdf = lights_.pmf(light) * light->pdf_li(prev_ctx, ray.d, at);
    L += beta * Le / carried_average(r_u + r_l * light_pdf, lambda);
  };
  while (crossings < kMaxCrossings) {
    SurfaceInteraction si;
    ++tally.rays;
    const bool hit = scene_.intersect(ray, &si);
    if (medium) {
      const MediumProperties mp = medium->properties(lambda);
      const SampledSpectrum sigma_t = mp.sigma_a + mp.sigma_s;
      const float t_end = hit ? si.t : kInfinity;
      const float u_dist = sampler.get_1d(), u_mode = sampler.get_1d();
      // Free flight by the hero wavelength: t has density sigma_t0 exp(-sigma_t0 t). With
      // sigma_t0 = 0 nothing happens in this medium for the hero (t = inf).
      const float t = sigma_t[0] > 0.f ? -std::log1p(-u_dist) / sigma_t[0] : kInfinity;
      if (t < t_end) {
        const SampledSpectrum T = beer_lambert(sigma_t, t);
        const float pdf = sigma_t[0] * T[0];  // > 0: t is finite
        // Emission at the collision (pbrt-v4's r_e weighting: every wavelength could have
        // sampled this collision with density sigma_t_j T_j).
        if (medium->emissive() && depth < max_depth_) {
          const SampledSpectrum r_e = r_u * sigma_t * T / pdf;
          if (!is_black(r_e)) L += beta * T / pdf * mp.sigma_a * mp.Le / carried_average(r_e, lambda);
        }
        if (u_mode < mp.sigma_a[0] / sigma_t[0]) break;  // absorbed
        if (depth++ >= max_depth_) break;
        // Scattered: the hero chose this with density T0 sigma_s0, wavelength j with T_j sigma_s_j.
        const float pdf_s = T[0] * mp.sigma_s[0];
        beta *= T * mp.sigma_s / pdf_s;
        r_u *= T * mp.sigma_s / pdf_s;
        if (!is_finite(beta) || is_black(beta) || is_black(r_u)) break;
        Scatterer at;
        at.p = ray.at(t);
        at.time = ray.time;
        at.d_in = ray.d;
        at.g = mp.g;
        at.medium = medium;
        if (!lights_.empty()) L += sample_light(at, beta, r_u, lambda, sampler, tally);
        // The phase function is sampled exactly: p / pdf = 1, so beta is unchanged.
        const Vec3 wi = sample_henyey_greenstein(ray.d, mp.g, sampler.get_2d());
        r_l = r_u / henyey_greenstein(glm::dot(ray.d, wi), mp.g);
        specular_bounce = false;
        prev_ctx = LightSampleContext{at.p, Vec3(0.f)};
        ray = Ray{at.p, wi, kInfinity, ray.time};
        continue;
      }
      // The segment is passed: probability T0 for the hero, T_j for the scatter strategy of
      // wavelength j; the light strategy does not sample it (see sample_light).
      const SampledSpectrum T = beer_lambert(sigma_t, t_end);
      if (!(T[0] > 0.f)) break;
      beta *= T / T[0];
      r_u *= T / T[0];
      r_l /= T[0];
    }
    if (!hit) {
      for (const Light* light : scene_.infinite_lights()) add_emission(light, light->Le(ray, lambda), nullptr);
      break;
    }
    if (si.area_light) add_emission(si.area_light, si.area_light->L(si, -ray.d, lambda), &si);
    const BSDF* bsdf = si.material ? si.material->bsdf(si, lambda, arena) : nullptr;
    if (!bsdf) {  // an interface: cross it, into the medium on the other side
      if (si.medium_interface) medium = si.medium_interface->towards(ray.d, si.n);
      ray = spawn_ray(si, ray.d);
      ++crossings;
      continue;
    }
    if (visible && depth == 0) *visible = visible_surface(si, *bsdf);  // a gbuffer film's first surface
    if (depth++ == max_depth_) break;
    Scatterer at;
    at.p = si.p;
    at.p_error = si.p_error;
    at.n = si.n;
    at.time = si.time;
    at.si = &si;
    at.bsdf = bsdf;
    at.medium = medium;
    if (!lights_.empty() && (bsdf->flags() & (kDiffuse | kGlossy)))
      L += sample_light(at, beta, r_u, lambda, sampler, tally);
    else
      ++tally.shadow_rays_skipped;
    std::optional<BSDFSample> bs = bsdf->sample_f(si.wo, sampler.get_1d(), sampler.get_2d());
    if (!bs || bs->pdf <= 0.f || is_black(bs->f)) break;
    beta *= bs->f * std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf;
    r_l = r_u / bs->pdf;
    specular_bounce = bs->is_specular();
    prev_ctx = LightSampleContext{si.p, si.n};
    if (si.medium_interface) medium = si.medium_interface->towards(bs->wi, si.n);
    ray = unit_ray(spawn_ray(si, bs->wi));
    if (!is_finite(beta)) break;
    // Light refracted into a subsurface material leaves elsewhere (no bounce counted, as pbrt-v4).
    const BSSRDF* bssrdf =
        (bs->flags & kTransmission) && si.material->has_subsurface() ? si.material->bssrdf(si, lambda, arena) : nullptr;
    if (bssrdf) {
      if (!continue_from_subsurface_exit(si, *bssrdf, lambda, sampler, arena, tally, beta, r_u, r_l, L, ray, medium,
                                         prev_ctx))
        break;
      specular_bounce = false;  // the path leaves through Sw, a diffuse lobe
    }
    // Russian roulette as `path`, on the throughput divided by the spectral MIS ratio (pbrt-v4).
    const SampledSpectrum rr_beta = beta / carried_average(r_u, lambda);
    const float q = lambda.secondary_terminated() ? rr_beta[0] : max_component(rr_beta);
    if (depth > 1 && q < std::min(rr_threshold_, 1.f)) {
      if (sampler.get_1d() >= q) break;
      beta /= q;
    }
  }
  return L;
}

}  // namespace eyetrace
