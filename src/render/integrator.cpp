#include "render/integrator.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "core/splatting_camera.h"
#include "render/film.h"
#include "render/replay_sampler.h"

namespace eyetrace {

// The film position is drawn first so that samplers can stratify it.
CameraSample draw_camera_sample(const Film& film, Sampler& sampler, IVec2 pixel, int index, bool uniform) {
  sampler.start_pixel_sample(pixel, index);
  const Vec2 u = sampler.get_pixel_2d();
  const FilterSample fs = uniform ? SplattingCamera::uniform_sample(u) : film.filter().sample(u);
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

namespace {

struct ThreadState {
  std::unique_ptr<Sampler> sampler;
  ScratchBuffer arena;
};

// Camera rays generated together: lens cameras trace a batch at once (Camera::generate_rays),
// which hides the latency of their dependent surface-by-surface arithmetic.
constexpr int kCameraBatch = 16;

// The camera that splats a smooth filter's weights around each wavelength's landing point, when
// this render can use it: a dispersive camera that does, a filter that is not constant (a box
// has its own splats) and not wider than the splats serve.
const SplattingCamera* smooth_splatter(const Camera& camera, const Filter& filter) {
  if (!camera.splats() || filter.constant()) return nullptr;
  const Vec2 r = filter.radius();
  if (!(r.x <= SplattingCamera::kMaxFilterRadius && r.y <= SplattingCamera::kMaxFilterRadius)) return nullptr;
  return dynamic_cast<const SplattingCamera*>(&camera);
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
  // light_splats: where the integrator's light splats go (null: radiance() alone).
  SampleBatch(const Integrator& integrator, const Camera& camera, Film& film, ThreadState& ts, RayTally& tally,
              uint64_t& lost, const PixelBounds& tile, bool allow_splat, LightSplats* light_splats)
      : integrator_(integrator),
        camera_(camera),
        film_(film),
        ts_(ts),
        tally_(tally),
        lost_(lost),
        tile_(tile),
        apart_(!light_splats && camera.traces_wavelengths_apart(film.filter(), allow_splat)),
        smooth_(allow_splat && !apart_ ? smooth_splatter(camera, film.filter()) : nullptr),
        splat_(allow_splat && !apart_ && camera.splats() && (film.filter().constant() || smooth_)),
        light_splats_(light_splats),
        replay_(*ts.sampler) {}
  bool splats() const { return splat_; }
  // Camera rays a sample makes (wavelengths apart: one per wavelength).
  int rays_per_sample() const { return apart_ ? kSpectrumSamples : 1; }
  ~SampleBatch() { flush(); }

  void add(IVec2 pixel, int index) {
    if (apart_) return add_apart(pixel, index);
    pixels_[count_] = pixel;
    indices_[count_] = index;
    const bool uniform =
        smooth_ && SplattingCamera::uniform_in_pixel(pixel, tile_.lo, tile_.hi, film_.filter().radius());
    samples_[count_] = draw_camera_sample(film_, *ts_.sampler, pixel, index, uniform);
    samples_[count_].splat = splat_;
    samples_[count_].splat_lo = tile_.lo;
    samples_[count_].splat_hi = tile_.hi;
    lambdas_[count_] = SampledWavelengths::sample_visible(samples_[count_].wavelength_u);
    if (++count_ == kCameraBatch) flush();
  }

  void flush() {
    if (smooth_)
      smooth_->generate_rays_splatting(samples_, lambdas_, rays_, splats_, size_t(count_));
    else
      camera_.generate_rays(samples_, lambdas_, rays_, size_t(count_));
    for (int i = 0; i < count_; i += apart_ ? kSpectrumSamples : 1) apart_ ? integrate_apart(i) : integrate(i);
    count_ = 0;
  }

 private:
  // Wavelengths apart (Camera::traces_wavelengths_apart): the sample's film and lens point
  // with its wavelengths rotated so that each is the hero once, kSpectrumSamples camera rays
  // in a row, each the hero's alone.
  void add_apart(IVec2 pixel, int index) {
    static_assert(kCameraBatch % kSpectrumSamples == 0);
    const CameraSample cs = draw_camera_sample(film_, *ts_.sampler, pixel, index);
    for (int k = 0; k < kSpectrumSamples; ++k, ++count_) {
      pixels_[count_] = pixel;
      indices_[count_] = index;
      samples_[count_] = hero_alone(cs, k, &lambdas_[count_]);
    }
    if (count_ == kCameraBatch) flush();
  }

  // Each wavelength's radiance from its own path, at the hero's plain weight; together they are
  // one sample of all the sample's wavelengths (each estimated by the one technique that made
  // it, so no MIS weights), added in its pixel. Every path starts from the sample's own sampler
  // dimensions: the wavelengths' paths are correlated, each unbiased. The first path's sampler
  // values are kept and given again to the others (render/replay_sampler.h).
  void integrate_apart(int first) {
    SampledSpectrum L(0.f);
    VisibleSurface visible;
    VisibleSurface* vs = film_.gbuffer() ? &visible : nullptr;
    bool recorded = false;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      const int i = first + k;
      const std::optional<CameraRay>& cr = rays_[i];
      if (!cr) {
        ++lost_;  // this wavelength's ray was lost: it adds zero (vignetting)
        continue;
      }
      if (recorded) {
        replay_.replay();
      } else {
        replay_.record(pixels_[i], indices_[i], kCameraDimensions);
        recorded = true;
      }
      L[k] = follow_path(i, k == 0 ? vs : nullptr, replay_)[0] * cr->hero_weight;
    }
    film_.add_sample(pixels_[first], L, sample_wavelengths(first), samples_[first].filter_weight, vs);
  }

  // Camera ray i's scene path from the sample's own sampler dimensions: its radiance (and, with
  // light tracing, its splats), and the visible surface's position differentials for a G-buffer.
  SampledSpectrum trace_path(int i, VisibleSurface* vs) {
    ts_.sampler->start_pixel_sample(pixels_[i], indices_[i], kCameraDimensions);
    return follow_path(i, vs, *ts_.sampler);
  }
  // The same from a sampler already at the path's first dimension.
  SampledSpectrum follow_path(int i, VisibleSurface* vs, Sampler& sampler) {
    const Ray& ray = rays_[i]->ray;
    SampledSpectrum L(0.f);
    if (light_splats_) {
      light_splats_->start_sample(indices_[i]);
      L = integrator_.radiance_and_splats(ray, lambdas_[i], sampler, ts_.arena, tally_, vs, *light_splats_);
    } else {
      L = integrator_.radiance(ray, lambdas_[i], sampler, ts_.arena, tally_, vs);
    }
    ts_.arena.reset();
    if (vs && vs->set) set_position_differentials(camera_, samples_[i], ray, ts_.sampler->samples_per_pixel(), *vs);
    return L;
  }

  void integrate(int i) {
    const std::optional<CameraRay>& cr = rays_[i];
    const float filter_weight = samples_[i].filter_weight;
    if (!cr) {
      // A lost camera ray is a zero-radiance sample: the pixel averages it in (vignetting).
      ++lost_;
      film_.add_sample(pixels_[i], RGB(0.f), filter_weight);
      if (box_splats()) add_lost_shares(i);
      return;
    }
    const SampledWavelengths& lambda = lambdas_[i];
    VisibleSurface visible;
    VisibleSurface* vs = film_.gbuffer() ? &visible : nullptr;
    SampledSpectrum L = trace_path(i, vs);
    const bool hero_alone = lambda.secondary_terminated();  // a dispersive dielectric split the path
    if (smooth_) {
      // Every wavelength splats around where it landed (core/splatting_camera.h), the hero too
      // when it goes alone: the film point may have been drawn uniformly in its pixel, which
      // only the splats turn into the filter's estimate. The sample's own pixel keeps its filter
      // weight, which the splats are averaged by.
      L *= hero_alone ? SampledSpectrum(cr->hero_weight) : cr->weight;
      film_.add_weight(pixels_[i], lambda, filter_weight, vs);
      film_.add_wavelength_splats(splats_[i].wavelength, L * std::abs(filter_weight), lambda);
      return;
    }
    if (hero_alone) {
      if (box_splats()) add_shares(i);
      film_.add_sample(pixels_[i], L * cr->hero_weight, lambda, filter_weight, vs);
      return;
    }
    L *= cr->weight;
    // Wavelengths a splatting camera sent to other pixels of the tile go there.
    move_landed(*cr, L,
                [&](IVec2 offset, const SampledSpectrum& one) { film_.add_splat(pixels_[i] + offset, one, lambda); });
    if (box_splats()) add_shares(i);
    film_.add_sample(pixels_[i], L, lambda, filter_weight, vs);
  }

  // Sample cs with its wavelengths rotated so that wavelength k is the hero, which goes alone
  // (the technique of wavelength k); lambda receives the rotated wavelengths.
  static CameraSample hero_alone(const CameraSample& cs, int k, SampledWavelengths* lambda) {
    CameraSample alone = cs;
    alone.hero_only = true;
    *lambda = SampledWavelengths::sample_visible(SampledWavelengths::rotated(cs.wavelength_u, k));
    return alone;
  }
  // Sample i's four wavelengths as drawn (before the camera or the path terminated any).
  SampledWavelengths sample_wavelengths(int i) const {
    return SampledWavelengths::sample_visible(samples_[i].wavelength_u);
  }
  // Calls add(offset, one) for every secondary wavelength k the camera sent to another pixel
  // (CameraRay::pixel_offset), `one` holding v[k] alone, which is moved out of v: v keeps what
  // stays in the sample's own pixel.
  template <typename Add>
  static void move_landed(const CameraRay& cr, SampledSpectrum& v, Add add) {
    for (int k = 1; k < kSpectrumSamples; ++k) {
      if (cr.pixel_offset[k] == IVec2(0)) continue;
      SampledSpectrum one(0.f);
      std::swap(one[k], v[k]);
      add(cr.pixel_offset[k], one);
    }
  }

  // A dispersive eye's wavelengths splatted one by one (box filter), normalised by their shares.
  bool box_splats() const { return splat_ && !smooth_; }
  // Each wavelength's share (CameraRay::share) where it landed: the film divides by their sums
  // (render/film.h, "Normalised splats"). At all four wavelengths, even when the path kept only
  // the hero: the shares count the camera's techniques, not the scene's.
  void add_shares(int i) {
    const CameraRay& cr = *rays_[i];
    const SampledWavelengths lambda = lambdas_[i].secondary_terminated() ? sample_wavelengths(i) : lambdas_[i];
    SampledSpectrum own = cr.share;  // the wavelengths that landed in the sample's pixel, at once
    move_landed(cr, own,
                [&](IVec2 offset, const SampledSpectrum& one) { film_.add_share(pixels_[i] + offset, one, lambda); });
    film_.add_share(pixels_[i], own, lambda);
  }
  // A lost camera ray's shares: each wavelength's share sums, over the samples, to the chance
  // that its technique (the same film and pupil point with that wavelength the hero) loses the
  // ray. Tracing each wavelength's own ray from the sample's point tells which lose it (l_k);
  // with m of the four lost, each lost one gets 4 / m: the hero is one of the m lost ones with
  // probability m / 4, so the expected share of wavelength k is l_k. Where the four are lost
  // together (almost everywhere) that is a share of 1 each, so vignetting adds no colour noise.
  void add_lost_shares(int i) {
    bool lost[kSpectrumSamples] = {true};
    int m = 1;
    for (int k = 1; k < kSpectrumSamples; ++k) {
      SampledWavelengths lambda;
      lost[k] = !camera_.generate_ray(hero_alone(samples_[i], k, &lambda), lambda);
      m += lost[k];
      ++tally_.camera_rays_for_shares;
    }
    SampledSpectrum share(0.f);
    for (int k = 0; k < kSpectrumSamples; ++k) share[k] = lost[k] ? float(kSpectrumSamples) / float(m) : 0.f;
    film_.add_share(pixels_[i], share, sample_wavelengths(i));
  }

  const Integrator& integrator_;
  const Camera& camera_;
  Film& film_;
  ThreadState& ts_;
  RayTally& tally_;
  uint64_t& lost_;
  PixelBounds tile_;
  bool apart_;
  const SplattingCamera* smooth_;
  bool splat_;
  LightSplats* light_splats_;
  ReplaySampler replay_;  // the per-wavelength paths' sampler values (wavelengths apart)
  IVec2 pixels_[kCameraBatch];
  int indices_[kCameraBatch];
  CameraSample samples_[kCameraBatch];
  SampledWavelengths lambdas_[kCameraBatch];
  std::optional<CameraRay> rays_[kCameraBatch];
  SampleSplats splats_[kCameraBatch];
  int count_ = 0;
};

// The next pass size: about `target` seconds at the speed of the last pass, at least one
// sample, and at most double the last pass so one slow start cannot make a huge pass.
int next_pass_samples(int last, double last_seconds, double target) {
  if (!(last_seconds > 0)) return 2 * last;
  double n = target * last / last_seconds;
  return int(std::clamp(n, 1.0, 2.0 * last));
}

// One render() call: the passes over the tiles this process owns (all of them unless it is one
// rank of a RenderGroup), uniform or adaptive, with progress, stopping and the collectives that
// keep ranks in step.
class RenderLoop {
 public:
  RenderLoop(const Integrator& integrator, const Camera& camera, const Sampler& sampler, Film& film,
             const RenderOptions& opts, RenderCounters& counters, TileProgress& tp, RenderGroup& group)
      : integrator_(integrator),
        camera_(camera),
        film_(film),
        opts_(opts),
        counters_(counters),
        tp_(tp),
        group_(group),
        b_(film.bounds()),
        spp_(sampler.samples_per_pixel()),
        states_([&] {
          return ThreadState{sampler.clone(), ScratchBuffer()};
        }),
        arena_(opts.threads > 0 ? opts.threads : tbb::this_task_arena::max_concurrency()),
        light_splats_(integrator.uses_light_splats(camera) && !tp.adaptive() && group.size() == 1) {
    if (light_splats_) {
      tile_splats_.assign(tp_.done.size(), LightSplats(camera));
      splatter_.emplace(film);
    }
    total_ = double(own_area()) * spp_;
    for (size_t t = 0; t < tp_.done.size(); ++t)
      if (group_.owns_tile(t, tp_.done.size())) samples_done_ += own_samples(t);
  }

  void uniform() {
    int pass = opts_.pass_samples > 0 ? opts_.pass_samples : 1;
    for (;;) {
      // Tiles behind (a resumed film stopped mid-pass) catch up first, to the same target.
      const int first = group_.min(own_min_done());
      if (group_.any(stopped()) || first >= spp_) break;
      int end = std::min(spp_, first + pass);
      if (light_splats_) end = std::min(end, first + light_splat_pass_cap());
      const double seconds = group_.max(timed_pass([&](size_t t) {
        if (tp_.done[t] >= end) return;
        render_tile(t, [&](IVec2) { return std::pair(tp_.done[t], end); });
        tp_.done[t] = end;
      }));
      // Every tile has finished the pass (a stop waits for it with light splats).
      if (light_splats_) splatter_->flush(film_, tile_splats_, first, end);
      if (group_.any(stopped())) break;
      if (opts_.on_pass) opts_.on_pass(tp_);
      if (opts_.pass_samples <= 0) pass = next_pass_samples(end - first, seconds, opts_.pass_seconds);
    }
  }

  // Pixel p takes [pixel_done, pixel_target) in a pass; the pass is whole when every pixel of
  // every rank has; then (films shared, so every rank decides alike) the next one is planned.
  void adaptive(const AdaptiveOptions& ao) {
    while (!tp_.complete(spp_) && !group_.any(stopped())) {
      total_ = double(samples_done_.load() + own_remaining());
      timed_pass([&](size_t t) {
        render_tile(t, [&](IVec2 p) { return std::pair(tp_.pixel_done[pixel(p)], tp_.pixel_target[pixel(p)]); });
        const PixelBounds tb = tp_.tile_bounds(t, b_);
        for (int y = tb.lo.y; y < tb.hi.y; ++y)
          for (int x = tb.lo.x; x < tb.hi.x; ++x)
            tp_.pixel_done[pixel(IVec2(x, y))] = tp_.pixel_target[pixel(IVec2(x, y))];
      });
      group_.share(film_, tp_);
      // Planned as soon as the pass is whole, stopped or not, so that a saved state is either
      // mid-pass or planned (complete exactly when no pixel has a target beyond its samples).
      if (tp_.pixel_done != tp_.pixel_target) break;
      plan_next_pass(film_, ao, tp_);
      if (group_.any(stopped())) break;
      if (opts_.on_pass) opts_.on_pass(tp_);
    }
  }

  void report(bool force) {
    if (!opts_.on_progress) return;
    if (force)
      progress_mutex_.lock();
    else if (!progress_mutex_.try_lock())
      return;
    auto now = std::chrono::steady_clock::now();
    if (force || now - last_report_ > std::chrono::milliseconds(250)) {
      last_report_ = now;
      // This rank's share of the work stands for the whole job's (tiles are dealt out evenly);
      // its rays, times the ranks, for the job's rate.
      const double f = tp_.complete(spp_) ? 1.0 : total_ > 0 ? double(samples_done_.load()) / total_ : 1.0;
      opts_.on_progress(std::min(f, 1.0), counters_.rays_traced.load() * uint64_t(group_.size()));
    }
    progress_mutex_.unlock();
  }

 private:
  bool stopped() const { return opts_.stop && opts_.stop->load(std::memory_order_relaxed); }
  size_t pixel(IVec2 p) const { return size_t(p.y - b_.lo.y) * size_t(b_.width()) + size_t(p.x - b_.lo.x); }

  uint64_t own_area() const {
    uint64_t a = 0;
    for (size_t t = 0; t < tp_.done.size(); ++t)
      if (group_.owns_tile(t, tp_.done.size())) a += tp_.tile_bounds(t, b_).area();
    return a;
  }
  uint64_t own_samples(size_t t) const {
    if (!tp_.adaptive()) return uint64_t(tp_.tile_bounds(t, b_).area()) * uint64_t(tp_.done[t]);
    uint64_t n = 0;
    const PixelBounds tb = tp_.tile_bounds(t, b_);
    for (int y = tb.lo.y; y < tb.hi.y; ++y)
      for (int x = tb.lo.x; x < tb.hi.x; ++x) n += uint64_t(tp_.pixel_done[pixel(IVec2(x, y))]);
    return n;
  }
  // Samples the pixels of this rank that still go on could take at most.
  uint64_t own_remaining() const {
    uint64_t r = 0;
    for (size_t t = 0; t < tp_.done.size(); ++t) {
      if (!group_.owns_tile(t, tp_.done.size())) continue;
      const PixelBounds tb = tp_.tile_bounds(t, b_);
      for (int y = tb.lo.y; y < tb.hi.y; ++y)
        for (int x = tb.lo.x; x < tb.hi.x; ++x) {
          const size_t i = pixel(IVec2(x, y));
          if (tp_.pixel_target[i] > tp_.pixel_done[i]) r += uint64_t(spp_ - tp_.pixel_done[i]);
        }
    }
    return r;
  }
  // The most samples per pixel a pass may take with light splats: kLightSplatPassSamples camera
  // samples, at least one per pixel.
  int light_splat_pass_cap() const {
    const uint64_t area = std::max<uint64_t>(1, own_area());
    return int(std::clamp<uint64_t>(kLightSplatPassSamples / area, 1, uint64_t(spp_)));
  }
  int own_min_done() const {
    int m = spp_;
    for (size_t t = 0; t < tp_.done.size(); ++t)
      if (group_.owns_tile(t, tp_.done.size())) m = std::min(m, tp_.done[t]);
    return m;
  }

  // Runs body(t) for every tile this rank owns, in parallel, skipping what is left once stopped;
  // returns (and counts) the seconds it took.
  template <typename Body>
  double timed_pass(Body&& body) {
    auto t0 = std::chrono::steady_clock::now();
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, tp_.done.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t != r.end(); ++t)
          if (group_.owns_tile(t, tp_.done.size()) && (light_splats_ || !stopped())) body(t);
      });
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    counters_.busy_seconds += seconds;
    return seconds;
  }

  // Tile t takes, for each pixel p, the samples [from, to) that range(p) gives; only this thread
  // touches tile t.
  template <typename Range>
  void render_tile(size_t t, Range&& range) {
    ThreadState& ts = states_.local();
    PixelBounds tb = tp_.tile_bounds(t, b_);
    RayTally tally;
    uint64_t lost = 0, n = 0;
    int rays_per_sample = 1;
    {
      SampleBatch batch(integrator_, camera_, film_, ts, tally, lost, tb, !tp_.adaptive(),
                        light_splats_ ? &tile_splats_[t] : nullptr);
      rays_per_sample = batch.rays_per_sample();
      if (batch.splats() || light_splats_) {
        // Sample index outermost: a pixel's splat sum then receives its neighbours' terms in an
        // order that passes do not change (see Film). 11 % slower than pixel by pixel (the
        // mono eye on the figure scene, before zsobol's tile cache), so only where splats happen
        // (uniform renders, where every pixel of the tile has the same range).
        auto [first, end] = range(tb.lo);
        for (int i = first; i < end; ++i)
          for (int y = tb.lo.y; y < tb.hi.y; ++y)
            for (int x = tb.lo.x; x < tb.hi.x; ++x) batch.add(IVec2(x, y), i);
        n = tb.area() * uint64_t(std::max(0, end - first));
      } else {
        for (int y = tb.lo.y; y < tb.hi.y; ++y)
          for (int x = tb.lo.x; x < tb.hi.x; ++x) {
            auto [from, to] = range(IVec2(x, y));
            for (int i = from; i < to; ++i) batch.add(IVec2(x, y), i);
            n += uint64_t(std::max(0, to - from));
          }
      }
    }
    counters_.samples += n;
    counters_.camera_rays += n * uint64_t(rays_per_sample);
    counters_.camera_rays_lost += lost;
    counters_.rays_traced += tally.rays;
    counters_.shadow_rays += tally.shadow_rays;
    counters_.shadow_rays_skipped += tally.shadow_rays_skipped;
    counters_.camera_rays_for_shares += tally.camera_rays_for_shares;
    samples_done_ += n;
    report(false);
  }

  const Integrator& integrator_;
  const Camera& camera_;
  Film& film_;
  const RenderOptions& opts_;
  RenderCounters& counters_;
  TileProgress& tp_;
  RenderGroup& group_;
  const PixelBounds& b_;
  const int spp_;
  tbb::enumerable_thread_specific<ThreadState> states_;
  tbb::task_arena arena_;
  double total_ = 0;
  std::atomic<uint64_t> samples_done_{0};
  std::mutex progress_mutex_;
  std::chrono::steady_clock::time_point last_report_ = std::chrono::steady_clock::now();
  const bool light_splats_;
  std::vector<LightSplats> tile_splats_;  // per tile: its splats of the pass in flight
  std::optional<LightSplatter> splatter_;
};

}  // namespace

void Integrator::render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
                        RenderCounters& counters) const {
  const PixelBounds& b = film.bounds();
  const AdaptiveOptions* adaptive = opts.adaptive;
  TileProgress own;
  TileProgress& tp = opts.tiles ? *opts.tiles : own;
  RenderGroup alone;
  RenderGroup& group = opts.group ? *opts.group : alone;
  if (adaptive && adaptive->max_spp != sampler.samples_per_pixel())
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
  if (uses_light_splats(camera) && (adaptive || group.size() > 1))
    warn(SourceLoc{}, adaptive ? "--adaptive: the integrator's light tracing strategies (bdpt, t = 1) need the same "
                                 "samples in every pixel; they are not used"
                               : "several processes: the integrator's light tracing strategies (bdpt, t = 1) "
                                 "add light to other ranks' pixels; they are not used");
  RenderLoop loop(*this, camera, sampler, film, opts, counters, tp, group);
  if (adaptive)
    loop.adaptive(*adaptive);
  else
    loop.uniform();
  loop.report(true);
  counters.nonfinite_samples = film.nonfinite_samples();
}

}  // namespace eyetrace
