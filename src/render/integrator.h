// Integrator interface: the base class owns the parallel tile loop (render()), each
// integrator supplies radiance() for one camera ray. render() works in passes of
// sample-index ranges so that it can stop between tiles, report each finished pass (for
// checkpoints), and resume from a saved film with the same result as an uninterrupted run.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>

#include "core/arena.h"
#include "core/camera.h"
#include "core/ray.h"
#include "core/sampled_spectrum.h"
#include "core/sampler.h"
#include "core/visible_surface.h"
#include "render/adaptive_sampling.h"
#include "render/light_splats.h"
#include "render/render_group.h"
#include "render/tile_progress.h"

namespace eyetrace {

class Scene;
class Film;

// Counters shared by all threads (relaxed atomics: totals only).
struct RenderCounters {
  std::atomic<uint64_t> camera_rays{0};
  std::atomic<uint64_t> camera_rays_lost{0};
  std::atomic<uint64_t> rays_traced{0};  // every ray given to Embree (closest or shadow)
  std::atomic<uint64_t> samples{0};      // camera samples taken
  std::atomic<uint64_t> nonfinite_samples{0};
  std::atomic<uint64_t> shadow_rays{0};          // of rays_traced: occlusion tests for light samples
  std::atomic<uint64_t> shadow_rays_skipped{0};  // scattering points that needed no occlusion test
  // Not in camera_rays: the rays a lost sample traces for its wavelengths' shares (box splats of
  // a dispersive eye, render/film.h "Normalised splats"); camera traces only, no scene path.
  std::atomic<uint64_t> camera_rays_for_shares{0};
  double busy_seconds = 0;  // time in passes, without waiting for other ranks (render thread only)
};

// Per-thread tally, flushed to RenderCounters once per tile to keep atomics off the hot path.
struct RayTally {
  uint64_t rays = 0;
  uint64_t shadow_rays = 0;
  // Scattering points where light sampling traced no shadow ray because it could not
  // contribute (no lights, a specular BSDF, a zero light sample or a zero f cos term).
  uint64_t shadow_rays_skipped = 0;
  uint64_t camera_rays_for_shares = 0;  // RenderCounters::camera_rays_for_shares
};

struct RenderOptions {
  int threads = 0;  // 0: all cores
  bool progress = true;
  // Called from the render loop with the fraction done; may print a progress line.
  std::function<void(double fraction, uint64_t rays)> on_progress;

  // In: the samples the film already holds (resuming a checkpoint); empty means none.
  // Out: where the render stopped. Null: the render keeps its own.
  TileProgress* tiles = nullptr;
  // Checked before each tile: once true, tiles not yet started in the pass are skipped and
  // render() returns (tiles in flight finish their pass range, so every tile stays whole). With
  // light splats the pass is finished first, so that every tile's splats are in the film.
  const std::atomic<bool>* stop = nullptr;
  // Samples per pixel in each pass; 0 picks pass sizes so that a pass takes about
  // pass_seconds (1, 2, 4, ... samples, at most doubling). The image does not depend on it.
  // With light splats a pass is at most kLightSplatPassSamples camera samples (at least one
  // sample per pixel), which bounds the splats held until the pass ends.
  int pass_samples = 0;
  double pass_seconds = 1.0;
  // Called after every complete pass, on the calling thread, with no tile in flight: the
  // film and `tiles` are consistent, so this is where a checkpoint can be written.
  std::function<void(const TileProgress&)> on_pass;
  // Adaptive sampling (render/adaptive_sampling.h); null: every pixel takes the sampler's
  // samples per pixel. Its max_spp must be the sampler's samples per pixel.
  const AdaptiveOptions* adaptive = nullptr;
  // The processes rendering this image together (render/render_group.h); null: this one alone.
  // Each renders the tiles it owns and at the end holds those alone (adaptive: every rank's
  // film is whole, shared after each pass); the caller collects them (RenderGroup::collect,
  // collect_image).
  RenderGroup* group = nullptr;
};

// The camera dimensions of one sample (pixel 2-D, lens 2-D, time, wavelength), drawn at the
// start of sample `index` of `pixel`; the integrator continues at dimension kCameraDimensions.
inline constexpr int kCameraDimensions = 6;
inline constexpr uint64_t kLightSplatPassSamples = uint64_t(1) << 18;
// uniform: the film point uniformly in the pixel's square instead of through the filter (a smooth
// splatting camera's: SplattingCamera::uniform_in_pixel, uniform_sample).
CameraSample draw_camera_sample(const Film& film, Sampler& sampler, IVec2 pixel, int index, bool uniform = false);

class Integrator {
 public:
  explicit Integrator(const Scene& scene) : scene_(scene) {}
  virtual ~Integrator() = default;

  // Radiance arriving along `ray` at the sample's wavelengths (camera weight not included).
  // A path that splits by wavelength terminates lambda's secondary wavelengths. `visible`, when
  // given (a gbuffer film), receives the first surface the ray sees.
  virtual SampledSpectrum radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                                   RayTally& tally, VisibleSurface* visible = nullptr) const = 0;
  virtual std::string to_string() const = 0;

  // Light splatting (render/light_splats.h): an integrator whose samples can also add light to
  // other pixels through `camera` (bdpt's t = 1 strategies) says so here, and makes that
  // estimate in radiance_and_splats, while radiance() makes the estimate without them (the
  // same expectation). The tile loop uses it in uniform renders of one process; adaptive
  // sampling and several processes take radiance() (see render()).
  virtual bool uses_light_splats(const Camera& /*camera*/) const { return false; }
  virtual SampledSpectrum radiance_and_splats(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                                              ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible,
                                              LightSplats& /*splats*/) const {
    return radiance(ray, lambda, sampler, arena, tally, visible);
  }

  // Renders every pixel of film's pixel bounds with `sampler`'s samples per pixel. Virtual for
  // integrators that need a loop of their own (sppm: camera and photon passes per iteration);
  // the others take the tile loop defined here.
  virtual void render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
                      RenderCounters& counters) const;

 protected:
  const Scene& scene_;
};

}  // namespace eyetrace
