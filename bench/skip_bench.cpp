// What the work eyetrace skips is worth, each as strategy A (what eyetrace does) against
// strategy B (the work done anyway), measured in one run. docs/performance.md quotes them.
//   build/bench/skip_bench --benchmark_counters_tabular=true
//
// - Pupil sampling: rays aimed into the region that passes the iris (the pupil tables) against
//   the naive strategy of ISET3d's realisticEye and pbrt's lens cameras without bounds: a
//   uniform point on the clear disc of the rear lens surface. Items are USEFUL rays (that leave
//   the cornea), so the time per item includes the wasted ones.
// - Stopping at the iris: a ray the iris blocks is not traced through the cornea, against
//   tracing every surface regardless.
#include <benchmark/benchmark.h>

#include <random>

#include "cameras/chief_ray.h"
#include "cameras/lens_system_camera.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {

const IVec2 kResolution(512, 512);

std::unique_ptr<LensSystemCamera> navarro() {
  SceneEntity e =
      parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 5 \"float fov\" 60", "Camera", "bench");
  CameraContext ctx{e.params, Transform(), kResolution, ""};
  std::unique_ptr<Camera> c = create_named_eye_camera("navarro")(ctx);
  return std::unique_ptr<LensSystemCamera>(static_cast<LensSystemCamera*>(c.release()));
}

// Retina points of random pixels, with the ray from each to a uniform point of the rear lens
// surface's clear disc (the naive strategy).
struct NaiveRays {
  std::vector<optics::Ray> rays;
};

NaiveRays naive_rays(const LensSystemCamera& cam, size_t n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const optics::CompiledSystem& sys = cam.system();
  const int rear = sys.image_index() - 1;
  const double radius = cam.prescription().surfaces[size_t(rear)].semi_diameter_mm;
  const double z = sys.vertex_z(rear);
  NaiveRays out;
  while (out.rays.size() < n) {
    auto rp = cam.retina_point(Vec2(float(kResolution.x * u(rng)), float(kResolution.y * u(rng))));
    if (!rp) continue;
    const double r = radius * std::sqrt(u(rng)), phi = kTwoPiDouble * u(rng);
    const glm::dvec3 target(r * std::cos(phi), r * std::sin(phi), z);
    out.rays.push_back({rp->position, target - rp->position});
  }
  return out;
}

void BM_PupilTables(benchmark::State& state) {
  auto cam = navarro();
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<CameraSample> samples(4096);
  for (CameraSample& cs : samples) {
    cs.p_film = Vec2(kResolution.x * u(rng), kResolution.y * u(rng));
    cs.p_lens = Vec2(u(rng), u(rng));
  }
  std::vector<std::optional<CameraRay>> out(samples.size());
  size_t useful = 0, tried = 0;
  for (auto _ : state) {
    cam->generate_rays(samples.data(), out.data(), samples.size());
    for (const auto& r : out) useful += r.has_value();
    tried += samples.size();
  }
  state.SetItemsProcessed(int64_t(useful));
  state.counters["useful_fraction"] = double(useful) / double(tried);
}
BENCHMARK(BM_PupilTables);

void BM_PupilNaiveDisc(benchmark::State& state) {
  auto cam = navarro();
  const NaiveRays naive = naive_rays(*cam, 4096);
  std::vector<optics::TraceResult> results(naive.rays.size());
  const optics::CompiledSystem& sys = cam->system();
  size_t useful = 0, tried = 0;
  for (auto _ : state) {
    sys.trace_range_batch(naive.rays.data(), results.data(), naive.rays.size(), sys.image_index() - 1, 0);
    for (const auto& r : results) useful += r.ok();
    tried += results.size();
  }
  state.SetItemsProcessed(int64_t(useful));
  state.counters["useful_fraction"] = double(useful) / double(tried);
}
BENCHMARK(BM_PupilNaiveDisc);

// Naive rays again, single-ray trace: A stops at the iris (as eyetrace does), B goes on
// through the cornea from where the iris plane was met, as if the iris were not checked until
// the end. Items are rays traced.
void BM_StopAtIris(benchmark::State& state) {
  auto cam = navarro();
  const NaiveRays naive = naive_rays(*cam, 4096);
  const optics::CompiledSystem& sys = cam->system();
  double sink = 0;
  for (auto _ : state)
    for (const optics::Ray& r : naive.rays) sink += sys.trace_range(r, sys.image_index() - 1, 0).ray.direction.z;
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(int64_t(state.iterations() * naive.rays.size()));
}
BENCHMARK(BM_StopAtIris);

void BM_TraceThroughIris(benchmark::State& state) {
  auto cam = navarro();
  const NaiveRays naive = naive_rays(*cam, 4096);
  const optics::CompiledSystem& sys = cam->system();
  const int stop = sys.stop_index();
  double sink = 0;
  for (auto _ : state)
    for (const optics::Ray& r : naive.rays) {
      optics::TraceResult at_stop = sys.trace_range(r, sys.image_index() - 1, stop + 1);
      const optics::Ray on = at_stop.ray;
      // Cross the iris plane without the aperture test, then the cornea.
      const double t = (sys.vertex_z(stop) - on.origin.z) / on.direction.z;
      const optics::Ray past{on.origin + t * on.direction, on.direction};
      sink += sys.trace_range(past, stop - 1, 0).ray.direction.z;
    }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(int64_t(state.iterations() * naive.rays.size()));
}
BENCHMARK(BM_TraceThroughIris);

}  // namespace
}  // namespace eyetrace
