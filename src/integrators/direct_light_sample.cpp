#include "integrators/direct_light_sample.h"

#include "core/material.h"
#include "core/sampling.h"
#include "render/scene.h"

namespace eyetrace {

SampledSpectrum sample_one_light(const Scene& scene, const PowerLightSampler& lights, const SurfaceInteraction& si,
                                 const BSDF& bsdf, const SampledWavelengths& lambda, Sampler& sampler,
                                 RayTally& tally) {
  const float u_light = sampler.get_1d();
  const Vec2 u = sampler.get_2d();
  float pmf = 0.f;
  // A sample that cannot contribute costs no shadow ray.
  auto skip = [&] {
    ++tally.shadow_rays_skipped;
    return SampledSpectrum(0.f);
  };
  const Light* light = lights.sample(u_light, &pmf);
  if (!light || pmf == 0.f) return skip();
  const std::optional<LightLiSample> ls = light->sample_li(LightSampleContext{si.p, si.n}, u, lambda);
  if (!ls || ls->pdf <= 0.f || is_black(ls->L)) return skip();
  const SampledSpectrum f = bsdf.f(si.wo, ls->wi) * std::abs(glm::dot(ls->wi, si.ns));
  if (is_black(f)) return skip();
  ++tally.rays;
  ++tally.shadow_rays;
  if (scene.occluded(spawn_ray_to(si, ls->p_light, ls->p_light_error, ls->n_light))) return SampledSpectrum(0.f);
  const float light_pdf = pmf * ls->pdf;
  if (light->is_delta()) return f * ls->L / light_pdf;
  return power_heuristic(light_pdf, bsdf.pdf(si.wo, ls->wi)) * f * ls->L / light_pdf;
}

}  // namespace eyetrace
