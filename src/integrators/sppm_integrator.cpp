#include "integrators/sppm_integrator.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/error.h"
#include "core/material.h"
#include "core/sampling.h"
#include "integrators/direct_light_sample.h"
#include "integrators/interface_crossings.h"
#include "integrators/sppm_pixel.h"
#include "integrators/visible_point_grid.h"
#include "render/film.h"
#include "render/scene.h"

namespace eyetrace {

namespace {

// Photons per deposit list: the unit of parallel work, merged in order.
constexpr int64_t kPhotonBatch = 4096;
// Batches traced before their deposits are added to the pixels (about 262,000 photons): enough
// work per group for many threads, few enough that the deposit lists stay small.
constexpr int64_t kBatchesPerMerge = 64;

// Van der Corput's radical inverse of i in `base`: each iteration's wavelengths and time, as
// pbrt-v4 draws them (bases 3 and 5), so that successive iterations cover them evenly.
float radical_inverse(unsigned base, uint64_t i) {
  const double inv = 1.0 / base;
  double f = inv, r = 0;
  for (; i > 0; i /= base, f *= inv) r += double(i % base) * f;
  return std::min(float(r), kOneMinusEpsilon);
}

// A photon's own random numbers: splitmix64 (Steele, Lea and Flood 2014) started from a hash of
// (seed, photon index), so a photon draws the same numbers whichever thread traces it.
class PhotonRng {
 public:
  PhotonRng(uint64_t seed, uint64_t index) : state_(mix(seed ^ mix(index + kGolden))) {}
  float get_1d() { return float(next() >> 40) * 0x1p-24f; }
  Vec2 get_2d() {
    const float a = get_1d();
    return Vec2(a, get_1d());
  }

 private:
  static constexpr uint64_t kGolden = 0x9E3779B97F4A7C15ull;
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint64_t next() { return mix(state_ += kGolden); }
  uint64_t state_;
};

void add_rgb(double sum[3], const RGB& v) {
  sum[0] += v.r;
  sum[1] += v.g;
  sum[2] += v.b;
}

}  // namespace

// One render() call: the per-pixel state and the passes of each iteration.
class SppmIntegrator::Run {
  // Members of Run rather than of the file's anonymous namespace: Run's fields and lambdas hold
  // them, and a class with linkage must not (gcc's -Wsubobject-linkage in a unity build).

  // One photon's flux landing within a visible point's radius.
  struct Deposit {
    uint32_t pixel;
    RGB phi;
  };

  struct SppmThreadState {
    std::unique_ptr<Sampler> sampler;
    ScratchBuffer camera_arena;  // visible points' BSDFs: kept until the iteration ends
    ScratchBuffer photon_arena;  // reset after every photon
    RayTally tally;
    uint64_t camera_rays = 0, lost = 0, nonfinite = 0;
  };

 public:
  Run(const SppmIntegrator& in, const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts)
      : in_(in),
        scene_(in.scene_),
        camera_(camera),
        film_(film),
        opts_(opts),
        b_(film.bounds()),
        pixels_(b_.area()),
        photons_(in.options_.photons_per_iteration > 0 ? uint64_t(in.options_.photons_per_iteration)
                                                       : uint64_t(b_.area())),
        states_([&] { return SppmThreadState{sampler.clone(), ScratchBuffer(), ScratchBuffer(), {}, 0, 0, 0}; }),
        arena_(opts.threads > 0 ? opts.threads : tbb::this_task_arena::max_concurrency()) {
    for (SppmPixel& px : pixels_) px.radius = in.options_.radius;
  }

  // Iteration `iter`: visible points, photons, the radius update.
  void iterate(int iter, int iterations) {
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(radical_inverse(3, uint64_t(iter)));
    const float time = radical_inverse(5, uint64_t(iter));
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(b_.lo.y, b_.hi.y), [&](const tbb::blocked_range<int>& r) {
        SppmThreadState& ts = states_.local();
        for (int y = r.begin(); y != r.end(); ++y)
          for (int x = b_.lo.x; x < b_.hi.x; ++x) camera_path(IVec2(x, y), iter, lambda, time, ts);
      });
    });
    report(2 * iter + 1, 2 * iterations);
    photon_pass(iter, lambda);
    report(2 * iter + 2, 2 * iterations);
    if (in_.record_) record(*in_.record_);
    arena_.execute([&] { tbb::parallel_for(size_t(0), pixels_.size(), [&](size_t i) { sppm_update(pixels_[i]); }); });
    for (SppmThreadState& ts : states_) ts.camera_arena.reset();
  }

  // The estimate after `iterations`, one sample of weight 1 per pixel.
  void write_film(int iterations) {
    for (int y = b_.lo.y; y < b_.hi.y; ++y)
      for (int x = b_.lo.x; x < b_.hi.x; ++x) {
        float L[3];
        sppm_estimate(pixels_[index(IVec2(x, y))], iterations, photons_, L);
        film_.add_sample(IVec2(x, y), RGB(L[0], L[1], L[2]), 1.f);
      }
  }

  void count(RenderCounters& c) const {
    for (const SppmThreadState& ts : states_) {
      c.samples += ts.camera_rays;
      c.camera_rays += ts.camera_rays;
      c.camera_rays_lost += ts.lost;
      c.rays_traced += ts.tally.rays;
      c.shadow_rays += ts.tally.shadow_rays;
      c.shadow_rays_skipped += ts.tally.shadow_rays_skipped;
      c.nonfinite_samples += ts.nonfinite;
    }
  }

 private:
  size_t index(IVec2 p) const { return size_t(p.y - b_.lo.y) * size_t(b_.width()) + size_t(p.x - b_.lo.x); }

  void report(int done, int total) {
    if (!opts_.on_progress) return;
    uint64_t rays = 0;
    for (const SppmThreadState& ts : states_) rays += ts.tally.rays;
    opts_.on_progress(double(done) / total, rays);
  }

  void record(IVec2 pixel) {
    if (pixel.x < b_.lo.x || pixel.y < b_.lo.y || pixel.x >= b_.hi.x || pixel.y >= b_.hi.y) return;
    const SppmPixel& px = pixels_[index(pixel)];
    in_.history_.radius.push_back(px.radius);
    in_.history_.n.push_back(px.n);
    in_.history_.m.push_back(px.m);
  }

  // The camera path of `pixel` in iteration `iter`: its direct light and visible point.
  void camera_path(IVec2 pixel, int iter, const SampledWavelengths& pass_lambda, float time, SppmThreadState& ts) {
    SppmPixel& px = pixels_[index(pixel)];
    CameraSample cs = draw_camera_sample(film_, *ts.sampler, pixel, iter);
    cs.time = time;
    SampledWavelengths lambda = pass_lambda;
    const std::optional<CameraRay> cr = camera_.generate_ray(cs, lambda);
    ++ts.camera_rays;
    if (!cr) {  // a lost camera ray adds nothing this iteration: the pixel averages it in
      ++ts.lost;
      return;
    }
    ts.sampler->start_pixel_sample(pixel, iter, kCameraDimensions);
    const SampledSpectrum L = trace_camera(cr->ray, lambda, ts, px.vp);
    // As the tile loop weights a path: the hero's own weight once the others are terminated.
    const SampledSpectrum w = lambda.secondary_terminated() ? SampledSpectrum(cr->hero_weight) : cr->weight;
    const RGB rgb = film_.sample_rgb(L * w, lambda);
    if (is_finite(rgb))
      add_rgb(px.ld, rgb);
    else
      ++ts.nonfinite;
    px.vp.beta *= w;
    if (!is_finite(px.vp.beta) || is_black(px.vp.beta)) px.vp = VisiblePoint{};
  }

  // Follows a camera ray as pbrt-v4's SPPM does: emission (MIS-weighted after a non-specular
  // bounce) and light sampling at each vertex until the first diffuse one (or a glossy one at
  // the last depth) leaves a visible point; one more ray there collects emission only.
  SampledSpectrum trace_camera(Ray ray, SampledWavelengths& lambda, SppmThreadState& ts, VisiblePoint& vp) const {
    SampledSpectrum L(0.f), beta(1.f);
    bool specular = true;  // the camera ray counts as specular: emission it sees is taken whole
    float p_b = 0.f, eta_scale = 1.f;
    LightSampleContext prev;
    int depth = 0;
    for (int crossings = 0; crossings < kMaxInterfaceCrossings; ++crossings) {
      SurfaceInteraction si;
      ++ts.tally.rays;
      const bool hit = scene_.intersect(ray, &si);
      auto emission = [&](const Light* light, const SampledSpectrum& Le, const SurfaceInteraction* at) {
        if (is_black(Le)) return;
        if (specular) {
          L += beta * Le;
          return;
        }
        const float p_l = in_.lights_.pmf(light) * light->pdf_li(prev, ray.d, at);
        L += beta * Le * power_heuristic(p_b, p_l);
      };
      if (!hit) {
        for (const Light* light : scene_.infinite_lights()) emission(light, light->Le(ray, lambda), nullptr);
        break;
      }
      if (si.area_light) emission(si.area_light, si.area_light->L(si, -ray.d, lambda), &si);
      if (!si.material) {  // an interface: pass through, no bounce counted
        ray = spawn_ray(si, ray.d);
        continue;
      }
      if (depth++ == in_.options_.max_depth || vp.bsdf) break;
      const BSDF* bsdf = si.material->bsdf(si, lambda, ts.camera_arena);
      if (!bsdf) {
        --depth;
        ray = spawn_ray(si, ray.d);
        continue;
      }
      const Vec3 wo = -ray.d;
      const unsigned flags = bsdf->flags();
      if (flags & (kDiffuse | kGlossy))
        L += beta * sample_one_light(scene_, in_.lights_, si, *bsdf, lambda, *ts.sampler, ts.tally);
      else
        ++ts.tally.shadow_rays_skipped;
      if ((flags & kDiffuse) || ((flags & kGlossy) && depth == in_.options_.max_depth))
        vp = VisiblePoint{si.p, wo, bsdf, beta, lambda.secondary_terminated()};
      const float uc = ts.sampler->get_1d();
      const std::optional<BSDFSample> bs = bsdf->sample_f(wo, uc, ts.sampler->get_2d());
      if (!bs || !(bs->pdf > 0.f) || is_black(bs->f)) break;
      specular = bs->is_specular();
      if (bs->flags & kTransmission) eta_scale *= sqr(bs->eta);
      beta *= bs->f * std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf;
      p_b = bs->pdf;
      // pbrt-v4's roulette for SPPM camera paths: on the throughput without the radiance
      // scaling of refraction, survival at least 5 % below 1.
      const float rr = max_component(beta * eta_scale);
      if (rr < 1.f) {
        const float q = std::max(0.05f, 1.f - rr);
        if (ts.sampler->get_1d() < q) break;
        beta /= 1.f - q;
      }
      if (!is_finite(beta)) break;
      prev = LightSampleContext{si.p, si.n};
      ray = spawn_ray(si, bs->wi);
    }
    return L;
  }

  // Shoots this iteration's photons in batches (in parallel), then adds each batch's deposits
  // to the pixels in batch order: the sums do not depend on which thread traced what. The batches
  // go in groups of kBatchesPerMerge, each group's deposits added before the next group starts,
  // so that the deposit lists held at once stay bounded whatever the photon count.
  void photon_pass(int iter, const SampledWavelengths& lambda) {
    const VisiblePointGrid grid(pixels_);
    if (grid.empty()) return;
    const int64_t batches = int64_t((photons_ + kPhotonBatch - 1) / kPhotonBatch);
    std::vector<std::vector<Deposit>> deposits(size_t(std::min(batches, kBatchesPerMerge)));
    for (int64_t group = 0; group < batches; group += kBatchesPerMerge) {
      const int64_t group_end = std::min(batches, group + kBatchesPerMerge);
      arena_.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int64_t>(group, group_end, 1), [&](const tbb::blocked_range<int64_t>& r) {
          SppmThreadState& ts = states_.local();
          for (int64_t batch = r.begin(); batch != r.end(); ++batch) {
            const uint64_t first = uint64_t(batch) * kPhotonBatch, end = std::min(photons_, first + kPhotonBatch);
            for (uint64_t i = first; i < end; ++i) {
              trace_photon(uint64_t(iter) * photons_ + i, grid, lambda, ts, deposits[size_t(batch - group)]);
              ts.photon_arena.reset();
            }
          }
        });
      });
      for (std::vector<Deposit>& list : deposits) {
        for (const Deposit& d : list) {
          SppmPixel& px = pixels_[d.pixel];
          add_rgb(px.phi, d.phi);
          ++px.m;
        }
        list.clear();  // keeps its capacity for the next group
      }
    }
  }

  // One photon from a light chosen by power (pbrt-v4): its flux lands on visible points near
  // every surface it meets after the first (light sampling already took the direct light).
  void trace_photon(uint64_t index, const VisiblePointGrid& grid, const SampledWavelengths& pass_lambda,
                    SppmThreadState& ts, std::vector<Deposit>& out) const {
    PhotonRng rng(in_.options_.seed, index);
    float pmf = 0.f;
    const Light* light = in_.lights_.sample(rng.get_1d(), &pmf);
    if (!light || !(pmf > 0.f)) return;
    const Vec2 u0 = rng.get_2d(), u1 = rng.get_2d();
    SampledWavelengths lambda = pass_lambda;
    const std::optional<LightLeSample> les = light->sample_le(u0, u1, lambda, 0.f);
    if (!les || !(les->pdf_pos > 0.f) || !(les->pdf_dir > 0.f) || is_black(les->L)) return;
    SampledSpectrum beta = les->abs_cos_theta(les->ray.d) * les->L / (pmf * les->pdf_pos * les->pdf_dir);
    if (is_black(beta) || !is_finite(beta)) return;
    Ray ray = les->ray;
    int crossings = 0;
    for (int depth = 0; depth < in_.options_.max_depth; ++depth) {
      SurfaceInteraction si;
      ++ts.tally.rays;
      if (!scene_.intersect(ray, &si)) break;
      const BSDF* bsdf = si.material ? si.material->bsdf(si, lambda, ts.photon_arena) : nullptr;
      if (!bsdf) {  // an interface: the photon passes, no bounce counted, nothing deposited
        if (++crossings == kMaxInterfaceCrossings) break;
        ray = spawn_ray(si, ray.d);
        --depth;
        continue;
      }
      const Vec3 wo = -ray.d;
      if (depth > 0) deposit(grid, si.p, wo, beta, lambda, ts, out);
      const float uc = rng.get_1d();
      const std::optional<BSDFSample> bs = bsdf->sample_f(wo, uc, rng.get_2d());
      if (!bs || !(bs->pdf > 0.f) || is_black(bs->f)) break;
      SampledSpectrum bnew = beta * bs->f * std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf;
      // Photons carry importance's adjoint: eyetrace's BSDFs scale refracted radiance by
      // 1 / eta^2, which flux does not take (pbrt-v4's TransportMode::Importance).
      if (bs->flags & kTransmission) bnew *= sqr(bs->eta);
      // Roulette on the change of throughput (pbrt-v4): unbiased, survivors reweighted.
      const float q = std::max(0.f, 1.f - max_component(bnew) / max_component(beta));
      if (rng.get_1d() < q) break;
      beta = bnew / (1.f - q);
      if (!is_finite(beta) || is_black(beta)) break;
      ray = spawn_ray(si, bs->wi);
    }
  }

  void deposit(const VisiblePointGrid& grid, const Vec3& p, const Vec3& wi, const SampledSpectrum& beta,
               const SampledWavelengths& lambda, SppmThreadState& ts, std::vector<Deposit>& out) const {
    grid.for_each_candidate(p, [&](uint32_t i) {
      const SppmPixel& px = pixels_[i];
      const Vec3 d = px.vp.p - p;
      if (double(glm::dot(d, d)) > px.radius * px.radius) return;
      const SampledSpectrum phi = px.vp.beta * beta * px.vp.bsdf->f(px.vp.wo, wi);
      SampledWavelengths photon_lambda = lambda;
      if (px.vp.secondary_terminated) photon_lambda.terminate_secondary();
      const RGB rgb = film_.sample_rgb(phi, photon_lambda);
      if (!is_finite(rgb)) {
        ++ts.nonfinite;
        return;
      }
      out.push_back({i, rgb});
    });
  }

  const SppmIntegrator& in_;
  const Scene& scene_;
  const Camera& camera_;
  Film& film_;
  const RenderOptions& opts_;
  const PixelBounds b_;
  std::vector<SppmPixel> pixels_;
  const uint64_t photons_;
  tbb::enumerable_thread_specific<SppmThreadState> states_;
  tbb::task_arena arena_;
};

SppmIntegrator::SppmIntegrator(const Scene& scene, const SppmOptions& options, SourceLoc loc)
    : Integrator(scene), options_(options), loc_(std::move(loc)), lights_(scene.lights()) {}

std::string SppmIntegrator::to_string() const {
  return fmt::format(
      "sppm integrator: maxdepth {}, {} photons per iteration, initial radius {}, {} light(s)", options_.max_depth,
      options_.photons_per_iteration > 0 ? std::to_string(options_.photons_per_iteration) : std::string("pixel count"),
      options_.radius, scene_.lights().size());
}

SampledSpectrum SppmIntegrator::radiance(const Ray&, SampledWavelengths&, Sampler&, ScratchBuffer&, RayTally&,
                                         VisibleSurface*) const {
  throw std::logic_error("sppm estimates whole images (render()), not the radiance of one camera ray");
}

void SppmIntegrator::render(const Camera& camera, const Sampler& sampler, Film& film, const RenderOptions& opts,
                            RenderCounters& counters) const {
  // What the tile loop offers and SPPM cannot: its pixels share photons, so they cannot be
  // sampled apart, split over processes or resumed from the film alone.
  auto refuse = [&](const std::string& what) {
    throw_error(loc_, fmt::format("integrator \"sppm\" does not support {}", what));
  };
  if (opts.adaptive) refuse("adaptive sampling (--adaptive)");
  if (opts.group && opts.group->size() > 1) refuse("rendering over several processes (mpirun)");
  if (opts.tiles && !opts.tiles->done.empty() && opts.tiles->max_done() > 0) refuse("resuming (--resume)");
  if (opts.on_pass) refuse("checkpoints (--checkpoint)");
  if (film.buckets().spectral()) refuse("the \"spectral\" film");
  if (film.gbuffer()) refuse("the \"gbuffer\" film");

  const auto t0 = std::chrono::steady_clock::now();
  history_ = PixelHistory{};
  const int iterations = sampler.samples_per_pixel();
  Run run(*this, camera, sampler, film, opts);
  int done = 0;
  while (done < iterations && !(opts.stop && opts.stop->load(std::memory_order_relaxed)))
    run.iterate(done++, iterations);
  if (done > 0) run.write_film(done);
  run.count(counters);
  TileProgress own;
  TileProgress& tp = opts.tiles ? *opts.tiles : own;
  tp = TileProgress::start(film.bounds());
  std::fill(tp.done.begin(), tp.done.end(), done);
  counters.busy_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  counters.nonfinite_samples += film.nonfinite_samples();
}

const PluginSpec& sppm_integrator_spec() {
  static const PluginSpec spec{
      "Integrator",
      "stochastic progressive photon mapping: iterations of camera paths to visible points and photons from "
      "the lights, with a shrinking gather radius (pbrt-v4's sppm)",
      "The iterations are the sampler's samples per pixel, as in pbrt-v4. Not with `--adaptive`, `--resume`, "
      "`--checkpoint`, several MPI processes, participating media, motion, the spectral or gbuffer film, or "
      "infinite lights with a portal (each refused with an error). Photons draw from "
      "their own random "
      "streams (splitmix64 from `seed`), not pbrt-v4's scrambled Halton points; the camera pass uses "
      "eyetrace's power light sampler (pbrt-v4: its BVH sampler); photons deposit only on surfaces with a "
      "material; a visible point enters each grid bucket once (pbrt-v4 lists it per cell, and a photon in a cell "
      "whose bucket holds it twice counts twice). As pbrt-v4, the pixel filter's weight is ignored.",
      {param::integer("maxdepth", 5).range(0, 10000).describe("bounces of camera paths and photons"),
       param::integer("photonsperiteration", -1)
           .at_least(-1)
           .describe("photons shot per iteration; -1 or 0: the number of pixels"),
       param::real("radius", 1).above(0).describe("initial search radius of every pixel (world units)"),
       param::integer("seed", 0).at_least(0).describe(
           "seed of the photons' random streams (default: the render's, --seed)")}};
  return spec;
}

std::unique_ptr<Integrator> create_sppm_integrator(const IntegratorContext& ctx) {
  const PluginParams p(ctx.params, sppm_integrator_spec(), "sppm");
  auto refuse = [&](const std::string& what) {
    throw_error(p.loc(), fmt::format("integrator \"sppm\" does not support {}", what));
  };
  if (ctx.scene.has_media()) refuse("participating media (render them with \"volpath\")");
  if (ctx.scene.has_motion()) refuse("motion (ActiveTransform, TransformTimes)");
  for (const Light* light : ctx.scene.lights())
    if (!light->emits_rays()) refuse("lights that cannot start light paths: \"infinite\" lights with a portal");
  SppmOptions o;
  o.max_depth = p.get_int("maxdepth");
  o.photons_per_iteration = p.get_int("photonsperiteration");
  o.radius = p.get_float("radius");
  o.seed = p.has("seed") ? uint64_t(p.get_int("seed")) : ctx.seed;
  return std::make_unique<SppmIntegrator>(ctx.scene, o, p.loc());
}

}  // namespace eyetrace
