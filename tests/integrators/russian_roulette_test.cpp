// Russian roulette (integrators/russian_roulette.h): "float rrthreshold" (pbrt-v3's and early
// pbrt-v4's: roulette only where the path throughput's largest component is below it) and
// "integer rrdepth" (eyetrace's: the first scattering vertex that plays). A camera inside a
// closed diffuse sphere (albedo 1/2) lit by a point light never escapes: without roulette
// every path runs to maxdepth, so the rays traced are known exactly: per camera ray, one
// intersection ray per bounce and one shadow ray per bounce (the light is never behind the
// inward-facing wall), and no ray after the last bounce (a point light cannot be hit). With
// roulette from vertex r, the throughput at vertex k is 2^-k until r, where the path survives
// with probability 2^-r and is reweighted to 1, and 1/2 at every vertex after (survival 1/2):
// vertex k > r is reached with probability 2^-(k-1).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr int kDepth = 6;
constexpr uint64_t kCameraRays = 16 * 16 * 16;

struct Result {
  uint64_t rays;
  double mean;
};

Result render(const std::string& rr) {
  const std::string text = fmt::format(
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 60\n"
      "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      "Sampler \"independent\" \"integer pixelsamples\" 16\nPixelFilter \"box\"\n"
      "Integrator \"path\" \"integer maxdepth\" {} {}\nWorldBegin\n"
      "LightSource \"point\" \"point3 from\" [0 0.3 0.2] \"rgb I\" [1 1 1]\n"
      "ReverseOrientation\nMaterial \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      "Shape \"sphere\" \"float radius\" 2\n",
      kDepth, rr);
  RenderSetup s = build_render_setup(parse_scene_string(text, "rr.pbrt", "."), {});
  RenderCounters c;
  RenderOptions o;
  o.threads = 1;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, c);
  EXPECT_EQ(c.camera_rays.load(), kCameraRays);
  EXPECT_EQ(c.shadow_rays_skipped.load(), 0u);
  Image img = s.film->image();
  double sum = 0;
  for (float v : img.pixels) sum += v;
  return {c.rays_traced.load(), sum / img.pixels.size()};
}

TEST(RussianRouletteThreshold, ZeroTurnsRouletteOff) {
  EXPECT_EQ(render("\"float rrthreshold\" 0").rays, kCameraRays * 2 * kDepth);
}

TEST(RussianRouletteDepth, BeyondTheLastVertexTurnsRouletteOff) {
  // Vertex kDepth traces no ray after it, so roulette there would change nothing either.
  EXPECT_EQ(render(fmt::format("\"integer rrdepth\" {}", kDepth)).rays, kCameraRays * 2 * kDepth);
}

// Expected rays per camera ray with roulette from vertex r (the header's probabilities).
double expected_rays_per_camera_ray(int r) {
  double reached = 0;
  for (int k = 1; k <= kDepth; ++k) reached += k <= r ? 1.0 : std::ldexp(1.0, -(k - 1));
  return 2 * reached;
}

// A path's ray count lies within 2 .. 2 kDepth, so the mean over 4096 paths has a standard
// deviation below 12 / 2 / 64 = 0.094 rays; 0.4 rays is more than 4 of them.
TEST(RussianRouletteDepth, RaysFollowTheSurvivalProbabilities) {
  for (int r : {2, 3, 5}) {
    const double per_camera_ray = double(render(fmt::format("\"integer rrdepth\" {}", r)).rays) / kCameraRays;
    EXPECT_NEAR(per_camera_ray, expected_rays_per_camera_ray(r), 0.4) << "rrdepth " << r;
  }
  // The default plays from the fifth vertex (Mitsuba 3's rr_depth; pbrt-v4 plays from the second).
  EXPECT_NEAR(double(render("").rays) / kCameraRays, expected_rays_per_camera_ray(5), 0.4);
}

// Both estimate the same radiance; 4096 samples per image, agreement within 3 %.
TEST(RussianRouletteDepth, EveryStartStaysUnbiased) {
  const Result off = render("\"float rrthreshold\" 0");
  for (int r : {1, 2, 5}) {
    const Result on = render(fmt::format("\"integer rrdepth\" {}", r));
    EXPECT_LT(on.rays, off.rays);
    EXPECT_NEAR(on.mean / off.mean, 1.0, 0.03) << "rrdepth " << r;
  }
}

TEST(RussianRouletteDepth, ZeroIsAnError) { EXPECT_THROW(render("\"integer rrdepth\" 0"), std::exception); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
