// Bidirectional path tracing, as pbrt-v4's "bdpt" integrator: per camera sample a camera
// subpath and a light subpath, connected by every strategy (s light vertices, t camera
// vertices): s = 0 (the camera path hits an emitter), s = 1 (a light sampled from a camera
// vertex), s >= 2 (a light-path vertex joined to a camera-path vertex by a shadow ray) and
// t = 1 (a light-path vertex joined to a point sampled on the camera's lens, splatted to the
// pixel where the camera sees it: render/light_splats.h), each weighted by pbrt-v4's MIS
// weight (integrators/bdpt_mis.h) over the strategies used. t = 1 needs a camera with
// importance (Camera::has_importance: the perspective camera) and the render loop's splats
// (uniform renders of one process); otherwise, and for a camera ray that leaves off the film,
// the weights are spread over t >= 2 alone: the image converges to the same answer, but light
// that only t = 1 reaches (a point light's caustic through glass onto a diffuse floor, seen
// directly) is missed, as by `path`.
// Surfaces only: scenes with participating media are rendered by `volpath` (with a warning).
// No Russian roulette (as pbrt-v4's bdpt). Wavelengths as `path`: a dispersive dielectric on
// either subpath terminates the secondary wavelengths of the whole sample.
#pragma once
#include "integrators/bdpt_vertex.h"
#include "integrators/light_sampler.h"
#include "render/integrator.h"
#include "scene/registry.h"

namespace eyetrace {

class BdptIntegrator : public Integrator {
 public:
  // Every light must be able to start a light path (Light::emits_rays).
  BdptIntegrator(const Scene& scene, int max_depth);
  SampledSpectrum radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                           RayTally& tally, VisibleSurface* visible = nullptr) const override;
  bool uses_light_splats(const Camera& camera) const override { return light_tracing_ && camera.has_importance(); }
  SampledSpectrum radiance_and_splats(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                                      ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible,
                                      LightSplats& splats) const override;
  // Off: t >= 2 alone, whatever the camera (tests compare with and without).
  void set_light_tracing(bool on) { light_tracing_ = on; }
  std::string to_string() const override;

 private:
  struct Walk;  // one sample's state: the sampler, arena and tally the subpaths use, the splats
  SampledSpectrum estimate(const Ray& ray, SampledWavelengths& lambda, Walk& w, VisibleSurface* visible) const;
  int camera_subpath(const Ray& ray, SampledWavelengths& lambda, Walk& w, BdptVertex* path,
                     VisibleSurface* visible) const;
  int light_subpath(SampledWavelengths& lambda, float time, Walk& w, BdptVertex* path) const;
  int random_walk(Ray ray, SampledWavelengths& lambda, Walk& w, SampledSpectrum beta, float pdf, int max_depth,
                  bool importance, BdptVertex* path, VisibleSurface* visible) const;
  SampledSpectrum connect(const SampledWavelengths& lambda, BdptVertex* light_path, BdptVertex* camera_path, int s,
                          int t, Walk& w) const;
  float mis_weight(BdptVertex* light_path, BdptVertex* camera_path, const BdptVertex& sampled, int s, int t,
                   const Walk& w) const;
  bool unoccluded(const BdptVertex& a, const BdptVertex& b, Walk& w) const;

  // Densities of a light vertex (pbrt-v4's PDFLight, PDFLightOrigin, InfiniteLightDensity).
  float pdf_light(const BdptVertex& light_vertex, const BdptVertex& next) const;
  float pdf_light_origin(const BdptVertex& light_vertex, const BdptVertex& next) const;
  float infinite_light_density(const Vec3& to_light) const;
  // Density with which `v` would generate `next`, having been reached from `prev`.
  // `camera`: the camera, for a camera vertex (t = 1 strategies).
  float pdf(const BdptVertex& v, const BdptVertex* prev, const BdptVertex& next, const Camera* camera = nullptr) const;
  SampledSpectrum emitted(const BdptVertex& v, const BdptVertex& towards, const SampledWavelengths& lambda) const;

  int max_depth_;
  PowerLightSampler lights_;
  float scene_radius_;
  bool light_tracing_ = true;
};

const PluginSpec& bdpt_integrator_spec();
std::unique_ptr<Integrator> create_bdpt_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
