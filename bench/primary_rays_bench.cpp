// Primary-ray throughput on a 204,800-triangle terrain, split into what Embree's traversal
// costs (BM_EmbreeTraversalOnly + BM_SceneOccludedOnly) and what eyetrace adds (camera,
// interaction, shading, sampling, film). Run:
//   build/bench/primary_rays_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>

#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {

constexpr int kGrid = 320;  // 320 x 320 quads = 204,800 triangles
constexpr int kRes = 256;

std::string terrain_scene(const std::string& integrator) {
  std::ostringstream s;
  s << "LookAt 0 -2.2 1.4  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" 50\n"
    << "Film \"rgb\" \"integer xresolution\" " << kRes << " \"integer yresolution\" " << kRes << "\n"
    << "Sampler \"independent\" \"integer pixelsamples\" 1\nIntegrator \"" << integrator << "\"\n"
    << "PixelFilter \"box\"\nWorldBegin\n"
    << "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0.3 0.2 0] \"rgb L\" [3 3 3]\n"
    << "Material \"diffuse\"\nShape \"trianglemesh\" \"point3 P\" [";
  for (int j = 0; j <= kGrid; ++j)
    for (int i = 0; i <= kGrid; ++i) {
      float x = 2.f * i / kGrid - 1.f, y = 2.f * j / kGrid - 1.f;
      s << x << ' ' << y << ' ' << 0.08f * std::sin(9 * x) * std::cos(7 * y) << ' ';
    }
  s << "] \"integer indices\" [";
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      int v = j * (kGrid + 1) + i;
      s << v << ' ' << v + 1 << ' ' << v + kGrid + 2 << ' ' << v << ' ' << v + kGrid + 2 << ' ' << v + kGrid + 1 << ' ';
    }
  s << "]\n";
  return s.str();
}

RenderSetup make_setup(const std::string& integrator) {
  SceneDescription desc = parse_scene_string(terrain_scene(integrator), "terrain.pbrt", ".");
  return build_render_setup(desc, {});
}

// One camera ray through each pixel centre, generated once outside the timed loops.
std::vector<Ray> primary_rays(const RenderSetup& s) {
  std::vector<Ray> rays;
  for (int y = 0; y < kRes; ++y)
    for (int x = 0; x < kRes; ++x) {
      CameraSample cs;
      cs.p_film = Vec2(x + 0.5f, y + 0.5f);
      rays.push_back(s.camera->generate_ray(cs)->ray);
    }
  return rays;
}

// Closest hits alone (Embree traversal plus turning the hit into an interaction), one ray
// per pixel: no camera, shading, shadow rays or film.
void BM_SceneIntersectOnly(benchmark::State& state) {
  RenderSetup s = make_setup("direct");
  std::vector<Ray> rays = primary_rays(s);
  size_t hits = 0;
  for (auto _ : state) {
    for (const Ray& r : rays) {
      SurfaceInteraction si;
      hits += s.scene->intersect(r, &si);
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_SceneIntersectOnly)->Unit(benchmark::kMillisecond);

// Embree's traversal alone: rtcIntersect1 on the same rays, no interaction. The difference
// to BM_SceneIntersectOnly is eyetrace's work of turning a hit into a SurfaceInteraction.
void BM_EmbreeTraversalOnly(benchmark::State& state) {
  RenderSetup s = make_setup("direct");
  std::vector<RTCRayHit> rays;
  for (const Ray& r : primary_rays(s)) {
    RTCRayHit rh{};
    rh.ray.org_x = r.o.x, rh.ray.org_y = r.o.y, rh.ray.org_z = r.o.z;
    rh.ray.dir_x = r.d.x, rh.ray.dir_y = r.d.y, rh.ray.dir_z = r.d.z;
    rh.ray.mask = 0xFFFFFFFFu;
    rays.push_back(rh);
  }
  size_t hits = 0;
  for (auto _ : state) {
    for (RTCRayHit rh : rays) {
      rh.ray.tfar = kInfinity;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      rtcIntersect1(s.scene->embree_scene(), &context, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_EmbreeTraversalOnly)->Unit(benchmark::kMillisecond);

// The shadow rays of the same frame alone (Embree occlusion queries towards the distant
// light from each primary hit): with BM_SceneIntersectOnly, all of Embree's share of a frame.
void BM_SceneOccludedOnly(benchmark::State& state) {
  RenderSetup s = make_setup("direct");
  std::vector<Ray> shadow;
  const Vec3 to_light = glm::normalize(Vec3(0.f, 0.f, 1.f) - Vec3(0.3f, 0.2f, 0.f));
  for (const Ray& r : primary_rays(s)) {
    SurfaceInteraction si;
    if (s.scene->intersect(r, &si)) shadow.push_back(spawn_ray(si, to_light));
  }
  size_t blocked = 0;
  for (auto _ : state)
    for (const Ray& r : shadow) blocked += s.scene->occluded(r);
  benchmark::DoNotOptimize(blocked);
  state.SetItemsProcessed(state.iterations() * shadow.size());
  state.counters["rays_per_frame"] = double(shadow.size());
}
BENCHMARK(BM_SceneOccludedOnly)->Unit(benchmark::kMillisecond);

// The whole render of one frame with one sample per pixel: camera + closest hit + shading +
// one shadow ray + film, single thread. Items are rays traced (primary and shadow).
void BM_RenderFrame(benchmark::State& state) {
  RenderSetup s = make_setup("direct");
  uint64_t rays = 0;
  for (auto _ : state) {
    RenderCounters c;
    RenderOptions o;
    o.threads = int(state.range(0));
    s.integrator->render(*s.camera, *s.sampler, *s.film, o, c);
    rays += c.rays_traced;
  }
  state.SetItemsProcessed(rays);
  state.counters["threads"] = double(state.range(0));
}
BENCHMARK(BM_RenderFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace eyetrace
