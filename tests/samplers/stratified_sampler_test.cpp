// The stratified sampler: each of a pixel's N samples takes its own 1/N stratum in every
// dimension and its own cell of the xsamples x ysamples grid in every 2D pair; the factory's
// pbrt-v4 parameters and --spp factorisation.
#include "samplers/stratified_sampler.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

ParameterList stratified_params(int xs, int ys, bool jitter) {
  ParameterList params;
  auto add = [&](const char* type, const char* name, std::vector<double> numbers, std::vector<bool> bools) {
    Param p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(numbers);
    p.bools = std::move(bools);
    params.add(std::move(p));
  };
  add("integer", "xsamples", {double(xs)}, {});
  add("integer", "ysamples", {double(ys)}, {});
  add("bool", "jitter", {}, {jitter});
  return params;
}

TEST(StratifiedSampler, EverySampleHasItsOwnStratum) {
  for (bool jitter : {true, false})
    for (IVec2 grid : {IVec2(4, 4), IVec2(5, 3), IVec2(1, 7)}) {
      ParameterList params = stratified_params(grid.x, grid.y, jitter);
      auto s = create_stratified_sampler(SamplerContext{params, IVec2(16, 16), 0, 3});
      int n = grid.x * grid.y;
      ASSERT_EQ(s->samples_per_pixel(), n);
      for (IVec2 pixel : {IVec2(0, 0), IVec2(9, 4)}) {
        std::vector<std::set<int>> strata_1d(5), cells_2d(4);
        for (int i = 0; i < n; ++i) {
          s->start_pixel_sample(pixel, i);
          Vec2 p = s->get_pixel_2d();
          cells_2d[0].insert(int(double(p.x) * grid.x) + grid.x * int(double(p.y) * grid.y));
          for (int d = 0; d < 5; ++d) strata_1d[size_t(d)].insert(int(double(s->get_1d()) * n));
          for (int d = 1; d < 4; ++d) {
            Vec2 u = s->get_2d();
            cells_2d[size_t(d)].insert(int(double(u.x) * grid.x) + grid.x * int(double(u.y) * grid.y));
          }
        }
        for (const auto& set : strata_1d) EXPECT_EQ(int(set.size()), n);
        for (const auto& set : cells_2d) EXPECT_EQ(int(set.size()), n);
      }
    }
}

TEST(StratifiedSampler, WithoutJitterSamplesAreStratumCentres) {
  ParameterList params = stratified_params(4, 2, false);
  auto s = create_stratified_sampler(SamplerContext{params, IVec2(4, 4), 0, 0});
  for (int i = 0; i < 8; ++i) {
    s->start_pixel_sample(IVec2(1, 1), i);
    float u = s->get_1d();
    EXPECT_FLOAT_EQ(u * 8.f - std::floor(u * 8.f), 0.5f);
    Vec2 v = s->get_2d();
    EXPECT_FLOAT_EQ(v.x * 4.f - std::floor(v.x * 4.f), 0.5f);
    EXPECT_FLOAT_EQ(v.y * 2.f - std::floor(v.y * 2.f), 0.5f);
  }
}

TEST(StratifiedSampler, DefaultsAreFourByFourJittered) {
  ParameterList params;
  auto s = create_stratified_sampler(SamplerContext{params, IVec2(4, 4), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 16);
  EXPECT_NE(s->to_string().find("xsamples=4 ysamples=4 jitter=true"), std::string::npos) << s->to_string();
}

TEST(StratifiedSampler, SppOverrideUsesTheSquarestFactorisation) {
  ParameterList params = stratified_params(4, 4, true);
  auto expect_grid = [&](int spp, const char* text) {
    auto s = create_stratified_sampler(SamplerContext{params, IVec2(4, 4), spp, 0});
    EXPECT_EQ(s->samples_per_pixel(), spp);
    EXPECT_NE(s->to_string().find(text), std::string::npos) << s->to_string();
  };
  expect_grid(12, "xsamples=4 ysamples=3");
  expect_grid(7, "xsamples=7 ysamples=1");
  expect_grid(64, "xsamples=8 ysamples=8");
}

TEST(StratifiedSampler, RejectsEmptyGrids) {
  ParameterList params = stratified_params(0, 4, true);
  EXPECT_THROW(create_stratified_sampler(SamplerContext{params, IVec2(4, 4), 0, 0}), SceneError);
  ParameterList huge = stratified_params(8192, 8192, true);
  EXPECT_THROW(create_stratified_sampler(SamplerContext{huge, IVec2(4, 4), 0, 0}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
