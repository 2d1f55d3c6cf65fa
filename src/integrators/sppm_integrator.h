// pbrt-v4's "sppm": stochastic progressive photon mapping (Hachisuka and Jensen 2009). Each
// iteration (one per sample per pixel) traces one camera path per pixel to its first diffuse
// vertex (or a glossy one at the last depth), adding emission and light sampling on the way and
// leaving a visible point there; then shoots photons from lights chosen by power, adds each
// photon that lands within a visible point's radius to that pixel, and shrinks the radius by
// the progressive rule (integrators/sppm_pixel.h). The image is the pixel's estimate, written to
// the film once at the end. Consistent: biased at any finite radius, the bias vanishing as the
// radius shrinks.
//
// Reproducible for any thread count: the camera pass draws from the sampler at (pixel,
// iteration); photon i of iteration k draws from its own random stream (seed, k, i); photons
// are traced in batches whose deposits are lists merged into the pixels in batch order.
#pragma once
#include "integrators/light_sampler.h"
#include "render/integrator.h"
#include "scene/registry.h"

namespace eyetrace {

struct SppmPixel;
struct SurfaceInteraction;
class BSDF;

struct SppmOptions {
  int max_depth = 5;
  int64_t photons_per_iteration = -1;  // <= 0: the film's pixel count
  float radius = 1.f;                  // initial search radius (world units)
  uint64_t seed = 0;                   // of the photons' random streams
};

class SppmIntegrator : public Integrator {
 public:
  // `loc`: the Integrator directive, named by errors found at render time.
  SppmIntegrator(const Scene& scene, const SppmOptions& options, SourceLoc loc);
  void render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
              RenderCounters& counters) const override;
  // SPPM estimates whole images, not the radiance of one ray: throws std::logic_error.
  SampledSpectrum radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                           RayTally& tally, VisibleSurface* visible = nullptr) const override;
  std::string to_string() const override;

  // For tests: after render(), each iteration's radius, N and M of one pixel (absolute raster
  // coordinates), recorded when `pixel` was set before render(); radius[i], n[i] are before
  // iteration i's update, m[i] that iteration's photons.
  struct PixelHistory {
    std::vector<double> radius, n;
    std::vector<uint64_t> m;
  };
  void record_pixel(IVec2 pixel) { record_ = pixel; }
  const PixelHistory& history() const { return history_; }

 private:
  class Run;
  SppmOptions options_;
  SourceLoc loc_;
  PowerLightSampler lights_;
  std::optional<IVec2> record_;
  mutable PixelHistory history_;
};

const PluginSpec& sppm_integrator_spec();
std::unique_ptr<Integrator> create_sppm_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
