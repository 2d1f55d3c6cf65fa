// Per-pixel deterministic sample streams: the same seed gives a bit-identical image with any
// number of threads, and another seed gives another image.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Image render_cornell(int threads, uint64_t seed, const std::string& sampler) {
  SceneDescription desc = parse_scene_file(std::string(EYETRACE_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
  RenderOverrides o;
  o.resolution = IVec2(48, 40);
  o.spp = 8;
  o.seed = seed;
  desc.sampler.name = sampler;
  desc.sampler.params = ParameterList();
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = threads;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  return s.film->image();
}

TEST(Render, SameSeedSameImageForAnyThreadCount) {
  for (const char* sampler : {"zsobol", "independent", "sobol", "halton", "stratified"}) {
    Image one = render_cornell(1, 3, sampler);
    Image two = render_cornell(2, 3, sampler);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_TRUE(one.pixels == two.pixels) << sampler << ": images differ between 1 and 2 threads";
    Image other = render_cornell(2, 4, sampler);
    EXPECT_FALSE(one.pixels == other.pixels) << sampler << ": seed has no effect";
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
