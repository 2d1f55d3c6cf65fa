// Integrator interface: the base class owns the parallel tile loop (render()), each
// integrator supplies radiance() for one camera ray.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>

#include "core/arena.h"
#include "core/camera.h"
#include "core/ray.h"
#include "core/sampler.h"

namespace eyetrace {

class Scene;
class Film;

// Counters shared by all threads (relaxed atomics: totals only).
struct RenderCounters {
  std::atomic<uint64_t> camera_rays{0};
  std::atomic<uint64_t> camera_rays_lost{0};
  std::atomic<uint64_t> rays_traced{0};      // every ray given to Embree (closest or shadow)
  std::atomic<uint64_t> samples{0};          // camera samples taken
  std::atomic<uint64_t> nonfinite_samples{0};
};

// Per-thread tally, flushed to RenderCounters once per tile to keep atomics off the hot path.
struct RayTally {
  uint64_t rays = 0;
};

struct RenderOptions {
  int threads = 0;  // 0: all cores
  bool progress = true;
  // Called from the render loop with the fraction done; may print a progress line.
  std::function<void(double fraction, uint64_t rays)> on_progress;
};

class Integrator {
 public:
  explicit Integrator(const Scene& scene) : scene_(scene) {}
  virtual ~Integrator() = default;

  // Radiance arriving along `ray` (camera weight not included).
  virtual RGB radiance(const Ray& ray, Sampler& sampler, ScratchBuffer& arena, RayTally& tally) const = 0;
  virtual std::string to_string() const = 0;

  // Renders every pixel of film's pixel bounds with `sampler`'s samples per pixel.
  void render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
              RenderCounters& counters) const;

 protected:
  const Scene& scene_;
};

}  // namespace eyetrace
