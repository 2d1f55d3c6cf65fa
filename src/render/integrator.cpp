#include "render/integrator.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <stdexcept>

#include "render/film.h"

namespace eyetrace {

namespace {

struct ThreadState {
  std::unique_ptr<Sampler> sampler;
  ScratchBuffer arena;
};

// The sampler dimensions a camera sample takes: pixel 2-D, lens 2-D, time, wavelength.
// The integrator restarts the sample's stream here after generating the camera rays.
constexpr int kCameraDimensions = 6;
// Camera rays generated together: lens cameras trace a batch at once (Camera::generate_rays),
// which hides the latency of their dependent surface-by-surface arithmetic.
constexpr int kCameraBatch = 16;

// The camera dimensions of one sample: the film position is drawn first so that samplers can
// stratify it.
CameraSample draw_camera_sample(const Film& film, Sampler& sampler, IVec2 pixel, int index) {
  sampler.start_pixel_sample(pixel, index);
  FilterSample fs = film.filter().sample(sampler.get_pixel_2d());
  CameraSample cs;
  cs.p_film = Vec2(pixel) + Vec2(0.5f) + fs.offset;
  cs.p_lens = sampler.get_2d();
  cs.time = sampler.get_1d();
  cs.wavelength_u = sampler.get_1d();
  cs.filter_weight = fs.weight;
  cs.filter = &film.filter();
  cs.filter_offset = fs.offset;
  return cs;
}

// Collects camera samples in the order the tile loop makes them and, per batch, generates
// their rays together and integrates each in the same order: the image is bit for bit the
// one of a sample-at-a-time loop, since every sample's stream restarts at its own
// (pixel, index, dimension) and each pixel still receives its samples in index order.
class SampleBatch {
 public:
  // tile: the pixels this thread owns, into which a dispersive camera may splat wavelengths
  // (box filter: see Film).
  // allow_splat false: every wavelength counts in the sample's own pixel only (adaptive
  // sampling gives the pixels of a tile different sample counts, which splats cannot share).
  SampleBatch(const Integrator& integrator, const Camera& camera, Film& film, ThreadState& ts, RayTally& tally,
              uint64_t& lost, const PixelBounds& tile, bool allow_splat)
      : integrator_(integrator),
        camera_(camera),
        film_(film),
        ts_(ts),
        tally_(tally),
        lost_(lost),
        tile_(tile),
        splat_(allow_splat && camera.splats() && film.filter().constant()) {}
  bool splats() const { return splat_; }
  ~SampleBatch() { flush(); }

  void add(IVec2 pixel, int index) {
    pixels_[count_] = pixel;
    indices_[count_] = index;
    samples_[count_] = draw_camera_sample(film_, *ts_.sampler, pixel, index);
    samples_[count_].splat = splat_;
    samples_[count_].splat_lo = tile_.lo;
    samples_[count_].splat_hi = tile_.hi;
    lambdas_[count_] = SampledWavelengths::sample_visible(samples_[count_].wavelength_u);
    if (++count_ == kCameraBatch) flush();
  }

  void flush() {
    camera_.generate_rays(samples_, lambdas_, rays_, size_t(count_));
    for (int i = 0; i < count_; ++i) integrate(i);
    count_ = 0;
  }

 private:
  void integrate(int i) {
    const std::optional<CameraRay>& cr = rays_[i];
    const float filter_weight = samples_[i].filter_weight;
    if (!cr) {
      // A lost camera ray is a zero-radiance sample: the pixel averages it in (vignetting).
      ++lost_;
      film_.add_sample(pixels_[i], RGB(0.f), filter_weight);
      return;
    }
    ts_.sampler->start_pixel_sample(pixels_[i], indices_[i], kCameraDimensions);
    SampledWavelengths& lambda = lambdas_[i];
    SampledSpectrum L = integrator_.radiance(cr->ray, lambda, *ts_.sampler, ts_.arena, tally_);
    ts_.arena.reset();
    if (lambda.secondary_terminated()) {
      film_.add_sample(pixels_[i], L * cr->hero_weight, lambda, filter_weight);
      return;
    }
    L *= cr->weight;
    // Wavelengths a splatting camera sent to other pixels of the tile go there.
    for (int k = 1; k < kSpectrumSamples; ++k) {
      if (cr->pixel_offset[k] == IVec2(0)) continue;
      SampledSpectrum one(0.f);
      std::swap(one[k], L[k]);
      film_.add_splat(pixels_[i] + cr->pixel_offset[k], one, lambda);
    }
    film_.add_sample(pixels_[i], L, lambda, filter_weight);
  }

  const Integrator& integrator_;
  const Camera& camera_;
  Film& film_;
  ThreadState& ts_;
  RayTally& tally_;
  uint64_t& lost_;
  PixelBounds tile_;
  bool splat_;
  IVec2 pixels_[kCameraBatch];
  int indices_[kCameraBatch];
  CameraSample samples_[kCameraBatch];
  SampledWavelengths lambdas_[kCameraBatch];
  std::optional<CameraRay> rays_[kCameraBatch];
  int count_ = 0;
};

// The next pass size: about `target` seconds at the speed of the last pass, at least one
// sample, and at most double the last pass so one slow start cannot make a huge pass.
int next_pass_samples(int last, double last_seconds, double target) {
  if (!(last_seconds > 0)) return 2 * last;
  double n = target * last / last_seconds;
  return int(std::clamp(n, 1.0, 2.0 * last));
}

}  // namespace

void Integrator::render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
                        RenderCounters& counters) const {
  const PixelBounds& b = film.bounds();
  const int spp = sampler.samples_per_pixel();
  const AdaptiveOptions* adaptive = opts.adaptive;
  TileProgress own;
  TileProgress& tp = opts.tiles ? *opts.tiles : own;
  if (adaptive && adaptive->max_spp != spp)
    throw std::invalid_argument("Integrator::render: adaptive max_spp differs from the sampler's samples per pixel");
  // A fresh progress (none, or TileProgress::start's) becomes an adaptive one when asked for.
  if (tp.done.empty() || (adaptive && !tp.adaptive() && tp.max_done() == 0)) {
    if (adaptive)
      start_adaptive(b, *adaptive, tp);
    else
      tp = TileProgress::start(b);
  }
  if (!tp.matches(b) || tp.adaptive() != bool(adaptive) || (adaptive && tp.pixel_done.size() != b.area()))
    throw std::invalid_argument("Integrator::render: tile progress does not match the film");
  tbb::enumerable_thread_specific<ThreadState> states([&] { return ThreadState{sampler.clone(), ScratchBuffer()}; });
  // Progress: uniform, the fraction of all samples; adaptive, of the samples taken and the
  // most the pixels still going could take (updated each pass, so it jumps as pixels stop).
  double total = double(b.area()) * spp;
  std::atomic<uint64_t> samples_done{tp.samples(b)};
  std::mutex progress_mutex;
  auto last_report = std::chrono::steady_clock::now();
  auto stopped = [&] { return opts.stop && opts.stop->load(std::memory_order_relaxed); };
  auto report = [&](bool force) {
    if (!opts.on_progress) return;
    if (force)
      progress_mutex.lock();
    else if (!progress_mutex.try_lock())
      return;
    auto now = std::chrono::steady_clock::now();
    if (force || now - last_report > std::chrono::milliseconds(250)) {
      last_report = now;
      const double f = tp.complete(spp) ? 1.0 : total > 0 ? double(samples_done.load()) / total : 1.0;
      opts.on_progress(std::min(f, 1.0), counters.rays_traced.load());
    }
    progress_mutex.unlock();
  };

  // Tile t takes, for each pixel, the samples [from, to) that `range` gives it; only this
  // thread touches tile t.
  auto render_tile = [&](size_t t, auto&& range) {
    ThreadState& ts = states.local();
    PixelBounds tb = tp.tile_bounds(t, b);
    RayTally tally;
    uint64_t lost = 0, n = 0;
    {
      SampleBatch batch(*this, camera, film, ts, tally, lost, tb, !adaptive);
      auto [first, end] = range(tb.lo);
      if (batch.splats()) {
        // Sample index outermost: a pixel's splat sum then receives its neighbours' terms in an
        // order that passes do not change (see Film). 11 % slower than pixel by pixel (the
        // mono eye on the figure scene), so only where splats happen. Uniform only: every
        // pixel of the tile has the same range.
        for (int i = first; i < end; ++i)
          for (int y = tb.lo.y; y < tb.hi.y; ++y)
            for (int x = tb.lo.x; x < tb.hi.x; ++x) batch.add(IVec2(x, y), i);
        n = tb.area() * uint64_t(end - first);
      } else {
        for (int y = tb.lo.y; y < tb.hi.y; ++y)
          for (int x = tb.lo.x; x < tb.hi.x; ++x) {
            auto [from, to] = range(IVec2(x, y));
            for (int i = from; i < to; ++i) batch.add(IVec2(x, y), i);
            n += uint64_t(std::max(0, to - from));
          }
      }
    }
    counters.samples += n;
    counters.camera_rays += n;
    counters.camera_rays_lost += lost;
    counters.rays_traced += tally.rays;
    counters.shadow_rays += tally.shadow_rays;
    counters.shadow_rays_skipped += tally.shadow_rays_skipped;
    samples_done += n;
    report(false);
  };
  int threads = opts.threads > 0 ? opts.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  auto for_each_tile = [&](auto&& body) {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, tp.done.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t != r.end(); ++t)
          if (!stopped()) body(t);
      });
    });
  };

  if (adaptive) {
    // Pixel p of tile t takes [pixel_done, pixel_target); a tile is done when all its pixels are.
    auto pixel = [&](IVec2 p) { return size_t(p.y - b.lo.y) * size_t(b.width()) + size_t(p.x - b.lo.x); };
    auto remaining = [&] {
      uint64_t r = 0;
      for (size_t i = 0; i < tp.pixel_done.size(); ++i)
        if (tp.pixel_target[i] > tp.pixel_done[i]) r += uint64_t(spp - tp.pixel_done[i]);
      return r;
    };
    while (!tp.complete(spp) && !stopped()) {
      total = double(samples_done.load() + remaining());
      for_each_tile([&](size_t t) {
        render_tile(t, [&](IVec2 p) { return std::pair(tp.pixel_done[pixel(p)], tp.pixel_target[pixel(p)]); });
        const PixelBounds tb = tp.tile_bounds(t, b);
        for (int y = tb.lo.y; y < tb.hi.y; ++y)
          for (int x = tb.lo.x; x < tb.hi.x; ++x)
            tp.pixel_done[pixel(IVec2(x, y))] = tp.pixel_target[pixel(IVec2(x, y))];
      });
      // Planned as soon as the pass is whole, stopped or not, so that a saved state is either
      // mid-pass or planned (complete exactly when no pixel has a target beyond its samples).
      if (tp.pixel_done != tp.pixel_target) break;
      plan_next_pass(film, *adaptive, tp);
      if (stopped()) break;
      if (opts.on_pass) opts.on_pass(tp);
    }
  } else {
    int pass = opts.pass_samples > 0 ? opts.pass_samples : 1;
    while (tp.min_done() < spp && !stopped()) {
      // Tiles behind (a resumed film stopped mid-pass) catch up first, to the same target.
      const int first = tp.min_done(), end = std::min(spp, first + pass);
      auto t0 = std::chrono::steady_clock::now();
      for_each_tile([&](size_t t) {
        if (tp.done[t] >= end) return;
        render_tile(t, [&](IVec2) { return std::pair(tp.done[t], end); });
        tp.done[t] = end;
      });
      if (stopped()) break;
      if (opts.on_pass) opts.on_pass(tp);
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (opts.pass_samples <= 0) pass = next_pass_samples(end - first, seconds, opts.pass_seconds);
    }
  }
  report(true);
  counters.nonfinite_samples = film.nonfinite_samples();
}

}  // namespace eyetrace
