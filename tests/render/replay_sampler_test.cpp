// The replay sampler gives a path exactly the values the underlying sampler gives it, whatever
// the path asks (the same calls as the recorded path, fewer, more, other kinds, or a path that
// repositions the sampler itself), and asks the underlying sampler nothing when it repeats the
// recorded path. The reference is a second copy of each sampler, asked directly.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../support/unity_id.h"
#include "render/replay_sampler.h"
#include "samplers/halton_sampler.h"
#include "samplers/independent_sampler.h"
#include "samplers/padded_sobol_sampler.h"
#include "samplers/pmj02bn_sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zsobol_sampler.h"
#include "scene/params.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using Factory = std::unique_ptr<Sampler> (*)(const SamplerContext&);

std::unique_ptr<Sampler> make(Factory factory) {
  const ParameterList params;
  return factory(SamplerContext{params, IVec2(16, 16), 64, 5});
}

// Counts the calls that reach the sampler it wraps.
class CountingSampler final : public Sampler {
 public:
  explicit CountingSampler(std::unique_ptr<Sampler> s) : s_(std::move(s)) {}
  int samples_per_pixel() const override { return s_->samples_per_pixel(); }
  void start_pixel_sample(IVec2 p, int i, int d) override { s_->start_pixel_sample(p, i, d); }
  float get_1d() override { return ++calls, s_->get_1d(); }
  Vec2 get_2d() override { return ++calls, s_->get_2d(); }
  Vec2 get_pixel_2d() override { return ++calls, s_->get_pixel_2d(); }
  std::unique_ptr<Sampler> clone() const override { return s_->clone(); }
  std::string to_string() const override { return s_->to_string(); }
  int calls = 0;

 private:
  std::unique_ptr<Sampler> s_;
};

// A path's calls: '1' get_1d, '2' get_2d, 'p' get_pixel_2d, 'r' start_pixel_sample at dimension 40.
std::vector<float> ask(Sampler& s, const std::string& calls, IVec2 pixel, int index) {
  std::vector<float> v;
  for (char c : calls) {
    if (c == '1') {
      v.push_back(s.get_1d());
    } else if (c == 'r') {
      s.start_pixel_sample(pixel, index, 40);
    } else {
      const Vec2 u = c == '2' ? s.get_2d() : s.get_pixel_2d();
      v.push_back(u.x);
      v.push_back(u.y);
    }
  }
  return v;
}

struct Case {
  const char* name;
  Factory factory;
};

const Case kSamplers[] = {{"independent", create_independent_sampler}, {"stratified", create_stratified_sampler},
                          {"halton", create_halton_sampler},           {"sobol", create_sobol_sampler},
                          {"paddedsobol", create_paddedsobol_sampler}, {"zsobol", create_zsobol_sampler},
                          {"pmj02bn", create_pmj02bn_sampler}};

TEST(ReplaySampler, EveryPathGetsTheUnderlyingSamplersValues) {
  const std::string recorded = "2121122";
  // Replayed paths: the same, shorter, longer, another kind at the third call, the 2D calls as
  // 1D ones, nothing, and one that repositions the sampler midway.
  const std::string replayed[] = {recorded, "212", recorded + "2121", "2112122", "1111111", "", "21r212"};
  const IVec2 pixel(3, 11);
  const int index = 17, dimension = 6;
  for (const Case& c : kSamplers) {
    SCOPED_TRACE(c.name);
    auto base = make(c.factory);
    auto reference = make(c.factory);
    ReplaySampler replay(*base);
    for (const std::string& path : replayed) {
      SCOPED_TRACE(path);
      replay.record(pixel, index, dimension);
      const std::vector<float> first = ask(replay, recorded, pixel, index);
      replay.replay();
      const std::vector<float> got = ask(replay, path, pixel, index);
      reference->start_pixel_sample(pixel, index, dimension);
      EXPECT_EQ(first, ask(*reference, recorded, pixel, index));
      reference->start_pixel_sample(pixel, index, dimension);
      EXPECT_EQ(got, ask(*reference, path, pixel, index));
    }
  }
}

TEST(ReplaySampler, RecordedPathThatRepositionsItself) {
  const IVec2 pixel(9, 2);
  for (const Case& c : kSamplers) {
    SCOPED_TRACE(c.name);
    auto base = make(c.factory);
    auto reference = make(c.factory);
    ReplaySampler replay(*base);
    replay.record(pixel, 4, 5);
    ask(replay, "12r21", pixel, 4);
    for (const std::string path : {"12r21", "1221", "2"}) {
      replay.replay();
      const std::vector<float> got = ask(replay, path, pixel, 4);
      reference->start_pixel_sample(pixel, 4, 5);
      EXPECT_EQ(got, ask(*reference, path, pixel, 4)) << path;
    }
  }
}

TEST(ReplaySampler, RepeatedPathAsksTheSamplerNothing) {
  CountingSampler base(make(create_zsobol_sampler));
  ReplaySampler replay(base);
  replay.record(IVec2(1, 1), 0, 6);
  ask(replay, "2212", IVec2(1, 1), 0);
  EXPECT_EQ(base.calls, 4);
  for (int k = 0; k < 3; ++k) {
    replay.replay();
    ask(replay, "2212", IVec2(1, 1), 0);
  }
  EXPECT_EQ(base.calls, 4);
  // A departure after two calls makes those two again on the sampler, then asks it.
  replay.replay();
  ask(replay, "2222", IVec2(1, 1), 0);
  EXPECT_EQ(base.calls, 4 + 2 + 2);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
