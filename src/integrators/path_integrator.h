// Unidirectional path tracing with next-event estimation and multiple importance sampling
// (power heuristic) between BSDF and light sampling, as pbrt-v4's "path" integrator.
// "direct" is the same estimator stopped after the first bounce (direct lighting only).
#pragma once
#include "core/ray.h"
#include "integrators/light_sampler.h"
#include "integrators/russian_roulette.h"
#include "render/integrator.h"
#include "scene/registry.h"

namespace eyetrace {

struct SurfaceInteraction;
class BSDF;
class BSSRDF;

class PathIntegrator : public Integrator {
 public:
  PathIntegrator(const Scene& scene, int max_depth, std::string name, RussianRoulette roulette = {});
  SampledSpectrum radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                           RayTally& tally, VisibleSurface* visible = nullptr) const override;
  std::string to_string() const override;

 private:
  // After a transmission into a subsurface material at `entry` (its BSSRDF there): moves the path to a sampled
  // exit point, adds light sampled there and samples Sw for the next ray. False ends the path.
  bool continue_from_subsurface_exit(const SurfaceInteraction& entry, const BSSRDF& bssrdf, SampledWavelengths& lambda,
                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally, SampledSpectrum& beta,
                                     SampledSpectrum& L, Ray& ray, float& prev_bsdf_pdf,
                                     LightSampleContext& prev_ctx) const;
  int max_depth_;
  std::string name_;
  RussianRoulette roulette_;
  PowerLightSampler lights_;
  // Whether any light can be hit by a ray (area and infinite lights; point, spot and distant
  // lights cannot). Without one, the BSDF-sampled ray after the last bounce, which exists
  // only to find emission, is not traced.
  bool hittable_lights_;
};

const PluginSpec& path_integrator_spec();
const PluginSpec& direct_integrator_spec();
const PluginSpec& volpath_integrator_spec();
std::unique_ptr<Integrator> create_path_integrator(const IntegratorContext& ctx);
std::unique_ptr<Integrator> create_direct_integrator(const IntegratorContext& ctx);
std::unique_ptr<Integrator> create_volpath_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
