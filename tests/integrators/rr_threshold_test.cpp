// Integrator "float rrthreshold" (pbrt-v3's and early pbrt-v4's Russian-roulette threshold):
// roulette only where the path throughput's largest component is below it. A camera inside a
// closed diffuse sphere (albedo 1/2) lit by a point light never escapes: without roulette
// every path runs to maxdepth, so the rays traced are known exactly: per camera ray, one
// intersection ray per bounce and one shadow ray per bounce (the light is never behind the
// inward-facing wall), and no ray after the last bounce (a point light cannot be hit).
#include <gtest/gtest.h>

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

// The throughput after the first bounce is 1/2 (diffuse, cosine-sampled): the default
// threshold 1 plays roulette from the second bounce on, and paths end early.
TEST(RussianRouletteThreshold, DefaultPlaysRouletteAndStaysUnbiased) {
  const Result off = render("\"float rrthreshold\" 0");
  const Result on = render("");
  EXPECT_LT(on.rays, off.rays * 3 / 4);
  // Both estimate the same radiance; 4096 samples per image, agreement within 3 %.
  EXPECT_NEAR(on.mean / off.mean, 1.0, 0.03);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
