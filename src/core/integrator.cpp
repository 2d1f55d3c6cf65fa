#include "core/integrator.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <mutex>

#include "core/film.h"

namespace eyetrace {

namespace {

constexpr int kTileSize = 16;

struct ThreadState {
  std::unique_ptr<Sampler> sampler;
  ScratchBuffer arena;
};

// One camera sample: the film position is drawn first so that samplers can stratify it.
void render_sample(const Integrator& integrator, const Camera& camera, Film& film, IVec2 pixel,
                   int index, ThreadState& ts, RayTally& tally, uint64_t* lost) {
  Sampler& sampler = *ts.sampler;
  sampler.start_pixel_sample(pixel, index);
  FilterSample fs = film.filter().sample(sampler.get_pixel_2d());
  CameraSample cs;
  cs.p_film = Vec2(pixel) + Vec2(0.5f) + fs.offset;
  cs.p_lens = sampler.get_2d();
  cs.time = sampler.get_1d();
  cs.wavelength_u = sampler.get_1d();
  cs.filter_weight = fs.weight;
  std::optional<CameraRay> cr = camera.generate_ray(cs);
  if (!cr) {
    // A lost camera ray is a zero-radiance sample: the pixel averages it in (vignetting).
    ++*lost;
    film.add_sample(pixel, RGB(0.f), fs.weight);
    return;
  }
  RGB L = integrator.radiance(cr->ray, sampler, ts.arena, tally) * cr->weight;
  film.add_sample(pixel, L, fs.weight);
  ts.arena.reset();
}

}  // namespace

void Integrator::render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
                        RenderCounters& counters) const {
  const PixelBounds& b = film.bounds();
  const int spp = sampler.samples_per_pixel();
  const IVec2 ntiles((b.width() + kTileSize - 1) / kTileSize, (b.height() + kTileSize - 1) / kTileSize);
  const size_t tile_count = size_t(ntiles.x) * ntiles.y;
  tbb::enumerable_thread_specific<ThreadState> states([&] { return ThreadState{sampler.clone(), ScratchBuffer()}; });
  std::atomic<size_t> tiles_done{0};
  std::mutex progress_mutex;
  auto last_report = std::chrono::steady_clock::now();

  auto render_tile = [&](size_t t) {
    ThreadState& ts = states.local();
    IVec2 lo = b.lo + IVec2(int(t % ntiles.x), int(t / ntiles.x)) * kTileSize;
    IVec2 hi = glm::min(lo + IVec2(kTileSize), b.hi);
    RayTally tally;
    uint64_t lost = 0;
    for (int y = lo.y; y < hi.y; ++y)
      for (int x = lo.x; x < hi.x; ++x)
        for (int i = 0; i < spp; ++i) render_sample(*this, camera, film, IVec2(x, y), i, ts, tally, &lost);
    uint64_t n = uint64_t(hi.x - lo.x) * uint64_t(hi.y - lo.y) * spp;
    counters.samples += n;
    counters.camera_rays += n;
    counters.camera_rays_lost += lost;
    counters.rays_traced += tally.rays;
    size_t done = ++tiles_done;
    if (opts.on_progress && progress_mutex.try_lock()) {
      auto now = std::chrono::steady_clock::now();
      if (now - last_report > std::chrono::milliseconds(250) || done == tile_count) {
        last_report = now;
        opts.on_progress(double(done) / tile_count, counters.rays_traced.load());
      }
      progress_mutex.unlock();
    }
  };

  int threads = opts.threads > 0 ? opts.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tile_count, 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t t = r.begin(); t != r.end(); ++t) render_tile(t);
    });
  });
  if (opts.on_progress) opts.on_progress(1.0, counters.rays_traced.load());
  counters.nonfinite_samples = film.nonfinite_samples();
}

}  // namespace eyetrace
