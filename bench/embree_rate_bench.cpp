// The render's ray rate against Embree's own rate for the same rays (issue 19, item 3): the
// figure scene (scenes/peripheral.pbrt) rendered through the Navarro eye or a pinhole with one
// thread, its rays recorded (Scene::record_rays: the closest-hit rays, here the camera rays, as
// the scene's direct integrator makes no bounce, and the shadow rays), then
// exactly those rays traced through the same Embree scene with nothing else. Run:
//   build/bench/embree_rate_bench --benchmark_counters_tabular=true
// BM_RenderAgainstEmbree times both in each iteration and reports render_over_embree, the
// render's rays per second per core as a fraction of Embree's (rtcIntersect1 + rtcOccluded1).
#include <benchmark/benchmark.h>

#include <ctime>

#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {

constexpr int kWidth = 240, kHeight = 160, kSpp = 8;

const char* camera_text(int camera) {
  return camera == 0 ? R"(Camera "navarro" "float fov" 50 "float pupildiameter" 5 "float wavelength" 589.3)"
                     : R"(Camera "pinhole" "float fov" 50)";
}
const char* camera_name(int camera) { return camera == 0 ? "navarro" : "pinhole"; }

RenderSetup figure_setup(int camera) {
  SceneDescription desc = parse_scene_file(std::string(EYETRACE_SOURCE_DIR) + "/scenes/peripheral.pbrt");
  RenderOverrides o;
  o.camera = parse_directive_text(camera_text(camera), "Camera", "bench");
  o.resolution = IVec2(kWidth, kHeight);
  o.spp = kSpp;
  return build_render_setup(desc, o);
}

// One single-threaded render (the film keeps accumulating; only the time matters); returns
// the rays it traced.
uint64_t render_once(RenderSetup& s) {
  RenderCounters c;
  RenderOptions o;
  o.threads = 1;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, c);
  return c.rays_traced;
}

RayRecord record(RenderSetup& s) {
  RayRecord rec;
  s.scene->record_rays(&rec);
  render_once(s);
  s.scene->record_rays(nullptr);
  return rec;
}

// Embree alone, one ray at a time, as Scene::intersect and Scene::occluded call it.
size_t trace_one_at_a_time(RTCScene scene, const RayRecord& rec) {
  size_t hits = 0;
  RTCIntersectContext context;
  for (const RTCRay& r : rec.closest) {
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = r;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  for (RTCRay r : rec.shadow) {
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, &r);
    hits += r.tfar < 0.f;
  }
  return hits;
}

// Embree's stream interface over the same rays in the recorded order (coherent hint: a
// tile's camera rays are recorded together).
size_t trace_streams(RTCScene scene, const RayRecord& rec, std::vector<RTCRayHit>& hits_buf,
                     std::vector<RTCRay>& shadow_buf) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (size_t i = 0; i < rec.closest.size(); ++i) {
    hits_buf[i].ray = rec.closest[i];
    hits_buf[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    hits_buf[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  shadow_buf = rec.shadow;
  rtcIntersect1M(scene, &context, hits_buf.data(), unsigned(hits_buf.size()), sizeof(RTCRayHit));
  rtcOccluded1M(scene, &context, shadow_buf.data(), unsigned(shadow_buf.size()), sizeof(RTCRay));
  size_t hits = 0;
  for (const RTCRayHit& h : hits_buf) hits += h.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  for (const RTCRay& r : shadow_buf) hits += r.tfar < 0.f;
  return hits;
}

void set_rate(benchmark::State& state, const RayRecord& rec) {
  const size_t n = rec.closest.size() + rec.shadow.size();
  state.SetItemsProcessed(int64_t(state.iterations() * n));
  state.counters["rays"] = double(n);
  state.counters["shadow_fraction"] = double(rec.shadow.size()) / double(n);
}

// The whole render, one thread: items are the rays it traced.
void BM_Render(benchmark::State& state) {
  RenderSetup s = figure_setup(int(state.range(0)));
  uint64_t rays = 0;
  for (auto _ : state) rays += render_once(s);
  state.SetItemsProcessed(int64_t(rays));
  state.SetLabel(camera_name(int(state.range(0))));
}
BENCHMARK(BM_Render)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_EmbreeOneAtATime(benchmark::State& state) {
  RenderSetup s = figure_setup(int(state.range(0)));
  const RayRecord rec = record(s);
  size_t hits = 0;
  for (auto _ : state) hits += trace_one_at_a_time(s.scene->embree_scene(), rec);
  benchmark::DoNotOptimize(hits);
  set_rate(state, rec);
  state.SetLabel(camera_name(int(state.range(0))));
}
BENCHMARK(BM_EmbreeOneAtATime)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_EmbreeStreams(benchmark::State& state) {
  RenderSetup s = figure_setup(int(state.range(0)));
  const RayRecord rec = record(s);
  std::vector<RTCRayHit> hits_buf(rec.closest.size());
  std::vector<RTCRay> shadow_buf;
  size_t hits = 0;
  for (auto _ : state) hits += trace_streams(s.scene->embree_scene(), rec, hits_buf, shadow_buf);
  benchmark::DoNotOptimize(hits);
  set_rate(state, rec);
  state.SetLabel(camera_name(int(state.range(0))));
}
BENCHMARK(BM_EmbreeStreams)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Both in one iteration, so the ratio is of two times measured side by side; process CPU time
// (one thread), so that other load on the machine does not count. The rays are the same
// ones, so the ratio of rates is Embree's share of the render's CPU time.
void BM_RenderAgainstEmbree(benchmark::State& state) {
  RenderSetup s = figure_setup(int(state.range(0)));
  const RayRecord rec = record(s);
  double render_s = 0, embree_s = 0;
  uint64_t render_rays = 0;
  size_t hits = 0;
  for (auto _ : state) {
    const std::clock_t t0 = std::clock();
    render_rays += render_once(s);
    const std::clock_t t1 = std::clock();
    hits += trace_one_at_a_time(s.scene->embree_scene(), rec);
    const std::clock_t t2 = std::clock();
    render_s += double(t1 - t0) / CLOCKS_PER_SEC;
    embree_s += double(t2 - t1) / CLOCKS_PER_SEC;
  }
  benchmark::DoNotOptimize(hits);
  const double n = double(rec.closest.size() + rec.shadow.size());
  const double render_rate = double(render_rays) / render_s;
  const double embree_rate = n * double(state.iterations()) / embree_s;
  state.counters["render_Mrays_s"] = render_rate * 1e-6;
  state.counters["embree_Mrays_s"] = embree_rate * 1e-6;
  state.counters["render_over_embree"] = render_rate / embree_rate;
  state.counters["rays_render_over_recorded"] = double(render_rays) / (n * double(state.iterations()));
  state.SetLabel(camera_name(int(state.range(0))));
}
BENCHMARK(BM_RenderAgainstEmbree)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace eyetrace
