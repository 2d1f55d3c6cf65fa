#include "integrators/volpath_integrator.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/henyey_greenstein.h"
#include "core/material.h"
#include "core/medium.h"
#include "core/sampling.h"
#include "integrators/interface_crossings.h"
#include "integrators/majorant_tracking.h"
#include "integrators/subsurface_exit.h"
#include "render/scene.h"

namespace eyetrace {

namespace {

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

// Ratio tracking (pbrt-v4's SampleLd): tentative collisions at the hero's majorant density
// pdf = T_maj[0] sigma_maj[0]; each multiplies the estimate by the null fraction T_maj
// sigma_n / pdf, the light strategy's ratio by T_maj sigma_maj / pdf (it samples exactly these
// points for every wavelength) and the scatter strategy's by T_maj sigma_n / pdf (delta
// tracking must also make each of them a null collision). Russian roulette ends estimates
// that have become small (pbrt-v4's 0.05 and 0.75).
void ratio_track(const Medium& medium, const Ray& ray, float t_end, VolPathIntegrator::ShadowTransmittance& tr,
                 const SampledWavelengths& lambda, TrackingRng& rng) {
  const SampledSpectrum T_maj = sample_majorants(
      medium, ray, t_end, rng.uniform(), rng, lambda,
      [&](const Vec3&, const MediumProperties& mp, const SampledSpectrum& sigma_maj, const SampledSpectrum& T_maj) {
        SampledSpectrum sigma_n = sigma_maj - mp.sigma_a - mp.sigma_s;
        for (int i = 0; i < kSpectrumSamples; ++i) sigma_n[i] = std::max(sigma_n[i], 0.f);
        const float pdf = T_maj[0] * sigma_maj[0];
        if (!(pdf > 0.f)) {
          tr.T = SampledSpectrum(0.f);
          return false;
        }
        tr.T *= T_maj * sigma_n / pdf;
        tr.r_l *= T_maj * sigma_maj / pdf;
        tr.r_u *= T_maj * sigma_n / pdf;
        if (max_component(tr.T) < 0.05f * carried_average(tr.r_l + tr.r_u, lambda)) {
          constexpr float q = 0.75f;
          if (rng.uniform() < q)
            tr.T = SampledSpectrum(0.f);
          else
            tr.T /= 1.f - q;
        }
        return !is_black(tr.T);
      });
  if (is_black(tr.T)) return;
  if (!(T_maj[0] > 0.f)) {  // the hero cannot pass what remains (underflow): nothing gets through
    tr.T = SampledSpectrum(0.f);
    return;
  }
  tr.T *= T_maj / T_maj[0];
  tr.r_l *= T_maj / T_maj[0];
  tr.r_u *= T_maj / T_maj[0];
}

}  // namespace

VolPathIntegrator::VolPathIntegrator(const Scene& scene, int max_depth, RussianRoulette roulette)
    : Integrator(scene), max_depth_(max_depth), roulette_(roulette), lights_(scene.lights()) {}

std::string VolPathIntegrator::to_string() const {
  return fmt::format("volpath integrator (participating media): maxdepth {}, {} light(s), power light sampling",
                     max_depth_, scene_.lights().size());
}

VolPathIntegrator::ShadowTransmittance VolPathIntegrator::transmittance(Ray ray, const Medium* medium, const Vec3& p_to,
                                                                        const Vec3& err_to, const Vec3& n_to,
                                                                        const SampledWavelengths& lambda,
                                                                        RayTally& tally) const {
  ShadowTransmittance tr;
  std::optional<TrackingRng> rng;  // seeded by the first ray through a heterogeneous medium
  for (int crossings = 0; crossings < kMaxInterfaceCrossings; ++crossings) {
    SurfaceInteraction si;
    ++tally.rays;
    ++tally.shadow_rays;
    const bool hit = scene_.intersect(ray, &si);
    if (hit && si.material) return ShadowTransmittance{SampledSpectrum(0.f)};  // blocked by a surface
    if (medium && medium->is_homogeneous()) {
      const MediumProperties mp = medium->properties(lambda);
      const SampledSpectrum T = beer_lambert(mp.sigma_a + mp.sigma_s, (hit ? si.t : ray.tmax) * glm::length(ray.d));
      tr.T *= T;
      tr.r_u *= T;
    } else if (medium) {
      const Ray unit = unit_ray(ray);
      const float t_end = (hit ? si.t : ray.tmax) * glm::length(ray.d);
      if (!rng) rng.emplace(hash_values(ray.o.x, ray.o.y, ray.o.z, ray.d.x, ray.d.y, ray.d.z));
      ratio_track(*medium, unit, t_end, tr, lambda, *rng);
    }
    if (!hit || is_black(tr.T)) return tr;
    if (si.medium_interface) medium = si.medium_interface->towards(ray.d, si.n);
    ray = spawn_ray_to(si, p_to, err_to, n_to);
  }
  return ShadowTransmittance{SampledSpectrum(0.f)};
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
//
// Heterogeneous segments on the same shadow ray are ratio-tracked (ratio_track above): the
// light strategy samples their tentative collisions, so its density gains prod T_maj_j
// sigma_maj_j per point (and T_maj_j for the rest of the segment), the scatter strategy's
// prod T_maj_j sigma_n_j (each must be a null collision), both relative to the hero's actual
// density; the estimate is T = prod T_maj sigma_n / pdf. The strategies' densities are products
// over segments, so a ray crossing both kinds multiplies the factors: exact segments put T_j
// into T and r_u and nothing into r_l, tracked ones their ratio-tracking factors into T, r_l,
// r_u (ShadowTransmittance). Then
//   beta f T L / avg_j(r_p_j (p_light r_l_j + p_scatter r_u_j)),
// which with exact segments only (r_l = 1, r_u = T) is the formula above. radiance() mirrors
// it: homogeneous segments update r_u and r_l as stated, heterogeneous ones by delta tracking
// (delta_track: null collisions multiply r_u by T_maj sigma_n / pdf and r_l by
// T_maj sigma_maj / pdf, pbrt-v4's updates). Each medium is one kind on both sides, so the
// path and the shadow ray agree on every segment's densities.
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
  const ShadowTransmittance tr =
      transmittance(shadow, medium, ls->p_light, ls->p_light_error, ls->n_light, lambda, tally);
  if (is_black(tr.T)) return SampledSpectrum(0.f);
  const float light_pdf = pmf * ls->pdf;
  const SampledSpectrum r_light = r_p * light_pdf * tr.r_l;
  if (light->is_delta()) return beta * f_hat * tr.T * ls->L / carried_average(r_light, lambda);
  return beta * f_hat * tr.T * ls->L / carried_average(r_light + r_p * tr.r_u * scatter_pdf, lambda);
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
  PathState state;
  SampledSpectrum &L = state.L, &beta = state.beta, &r_u = state.r_u, &r_l = state.r_l;
  int& depth = state.depth;
  bool& specular_bounce = state.specular_bounce;
  LightSampleContext& prev_ctx = state.prev_ctx;
  Ray ray = unit_ray(camera_ray);
  const Medium* medium = scene_.camera_medium();
  int crossings = 0;
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
  while (crossings < kMaxInterfaceCrossings) {
    SurfaceInteraction si;
    ++tally.rays;
    const bool hit = scene_.intersect(ray, &si);
    if (medium && !medium->is_homogeneous()) {
      const MediumEvent event = delta_track(*medium, ray, hit ? si.t : kInfinity, state, lambda, sampler, tally);
      if (event == MediumEvent::Terminated) break;
      if (event == MediumEvent::Scattered) continue;
    } else if (medium) {
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
    const float uc = sampler.get_1d();  // before the 2-D sample: argument order is unspecified
    std::optional<BSDFSample> bs = bsdf->sample_f(si.wo, uc, sampler.get_2d());
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
    if (roulette_.terminates(depth, RussianRoulette::weight(rr_beta, lambda), sampler, beta)) break;
  }
  return L;
}

VolPathIntegrator::MediumEvent VolPathIntegrator::delta_track(const Medium& medium, Ray& ray, float t_end, PathState& s,
                                                              const SampledWavelengths& lambda, Sampler& sampler,
                                                              RayTally& tally) const {
  // Two sampler dimensions, as the homogeneous path: the first distance, and the seed of the
  // numbers for the rest of the tracking.
  const float u_dist = sampler.get_1d();
  TrackingRng rng(hash_values(sampler.get_1d(), s.depth));
  MediumEvent event = MediumEvent::Passed;
  const SampledSpectrum T_maj = sample_majorants(
      medium, ray, t_end, u_dist, rng, lambda,
      [&](const Vec3& p, const MediumProperties& mp, const SampledSpectrum& sigma_maj, const SampledSpectrum& T_maj) {
        // Emission at every tentative collision (pbrt-v4's r_e: any wavelength could have
        // sampled this point with density sigma_maj_j T_maj_j).
        const float pdf = sigma_maj[0] * T_maj[0];
        if (s.depth < max_depth_ && !is_black(mp.Le) && pdf > 0.f) {
          const SampledSpectrum r_e = s.r_u * sigma_maj * T_maj / pdf;
          if (!is_black(r_e)) s.L += s.beta * T_maj / pdf * mp.sigma_a * mp.Le / carried_average(r_e, lambda);
        }
        // Absorption, real scattering or a null collision, with the hero's probabilities
        // (normalised: a majorant bounds sigma_t, so the null one is never negative in exact
        // arithmetic; rounding is clamped).
        const float p_absorb = mp.sigma_a[0] / sigma_maj[0], p_scatter = mp.sigma_s[0] / sigma_maj[0];
        const float p_null = std::max(0.f, 1.f - p_absorb - p_scatter);
        const float u = rng.uniform() * (p_absorb + p_scatter + p_null);
        if (u < p_absorb) {
          event = MediumEvent::Terminated;
          return false;
        }
        if (u < p_absorb + p_scatter) {
          if (s.depth++ >= max_depth_) {
            event = MediumEvent::Terminated;
            return false;
          }
          const float pdf_s = T_maj[0] * mp.sigma_s[0];
          s.beta *= T_maj * mp.sigma_s / pdf_s;
          s.r_u *= T_maj * mp.sigma_s / pdf_s;
          if (!is_finite(s.beta) || is_black(s.beta) || is_black(s.r_u)) {
            event = MediumEvent::Terminated;
            return false;
          }
          Scatterer at;
          at.p = p;
          at.time = ray.time;
          at.d_in = ray.d;
          at.g = mp.g;
          at.medium = &medium;
          if (!lights_.empty()) s.L += sample_light(at, s.beta, s.r_u, lambda, sampler, tally);
          const Vec3 wi = sample_henyey_greenstein(ray.d, mp.g, sampler.get_2d());  // p / pdf = 1
          s.r_l = s.r_u / henyey_greenstein(glm::dot(ray.d, wi), mp.g);
          s.specular_bounce = false;
          s.prev_ctx = LightSampleContext{p, Vec3(0.f)};
          ray = Ray{p, wi, kInfinity, ray.time};
          event = MediumEvent::Scattered;
          return false;
        }
        // Null collision: the hero chose it with density T_maj0 sigma_n0; the light strategy
        // would have sampled the point with T_maj sigma_maj (ratio tracking).
        SampledSpectrum sigma_n = sigma_maj - mp.sigma_a - mp.sigma_s;
        for (int i = 0; i < kSpectrumSamples; ++i) sigma_n[i] = std::max(sigma_n[i], 0.f);
        const float pdf_n = T_maj[0] * sigma_n[0];
        if (!(pdf_n > 0.f)) {
          event = MediumEvent::Terminated;
          return false;
        }
        s.beta *= T_maj * sigma_n / pdf_n;
        s.r_u *= T_maj * sigma_n / pdf_n;
        s.r_l *= T_maj * sigma_maj / pdf_n;
        if (!is_finite(s.beta) || is_black(s.beta) || is_black(s.r_u)) {
          event = MediumEvent::Terminated;
          return false;
        }
        return true;
      });
  if (event != MediumEvent::Passed) return event;
  // Passed to the end: probability T_maj0 for the hero, T_maj_j for either strategy.
  if (!(T_maj[0] > 0.f)) return MediumEvent::Terminated;
  s.beta *= T_maj / T_maj[0];
  s.r_u *= T_maj / T_maj[0];
  s.r_l *= T_maj / T_maj[0];
  return is_finite(s.beta) && !is_black(s.beta) ? MediumEvent::Passed : MediumEvent::Terminated;
}

}  // namespace eyetrace
