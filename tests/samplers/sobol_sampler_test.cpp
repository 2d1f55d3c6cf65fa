// The global Sobol' sampler: sample j of pixel p must be the j-th Sobol' point (in index order)
// whose first two coordinates, scaled to the image, fall in p, found here by brute force; the
// film positions of a pixel's 2^k samples form a (0,k,2)-net; padding past the matrices.
#include "samplers/sobol_sampler.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>
#include <set>

#include "core/error.h"
#include "samplers/lowdiscrepancy.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

ParameterList sobol_params(int spp, const std::string& randomization) {
  ParameterList params;
  Param n;
  n.type = "integer";
  n.name = "pixelsamples";
  n.numbers = {double(spp)};
  params.add(n);
  if (!randomization.empty()) {
    Param r;
    r.type = "string";
    r.name = "randomization";
    r.strings = {randomization};
    params.add(r);
  }
  return params;
}

TEST(SobolSampler, PixelSamplesAreTheSobolPointsInsideThePixel) {
  for (IVec2 res : {IVec2(1, 1), IVec2(8, 8), IVec2(5, 3), IVec2(16, 9)}) {
    const int spp = 8;
    int scale = int(std::bit_ceil(uint32_t(std::max(res.x, res.y))));
    // Brute force: walk the indices in order and deal each point to the pixel it lands in.
    std::map<std::pair<int, int>, std::vector<uint64_t>> points;
    for (uint64_t i = 0; i < uint64_t(scale) * scale * spp; ++i) {
      int px = int(uint64_t(sobol_bits(i, 0)) * scale >> 32), py = int(uint64_t(sobol_bits(i, 1)) * scale >> 32);
      points[{px, py}].push_back(i);
    }
    ParameterList params = sobol_params(spp, "none");
    auto s = create_sobol_sampler(SamplerContext{params, res, 0, 0});
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const auto& indices = points[{x, y}];
        ASSERT_EQ(int(indices.size()), spp);
        for (int j = 0; j < spp; ++j) {
          s->start_pixel_sample(IVec2(x, y), j);
          Vec2 u = s->get_pixel_2d();
          uint64_t i = indices[size_t(j)];
          double ex = double(sobol_bits(i, 0)) * 0x1p-32 * scale - x,
                 ey = double(sobol_bits(i, 1)) * 0x1p-32 * scale - y;
          EXPECT_NEAR(u.x, ex, 1e-6) << "res " << res.x << "x" << res.y << " pixel " << x << "," << y << " j " << j;
          EXPECT_NEAR(u.y, ey, 1e-6);
          // Later dimensions come from the same index (randomization "none").
          EXPECT_EQ(s->get_1d(), sobol_sample(i, 2, NoRandomizer()));
        }
      }
  }
}

TEST(SobolSampler, FilmPositionsOfAPixelAreANet) {
  for (int k : {3, 4, 6}) {
    int n = 1 << k;
    ParameterList params = sobol_params(n, "fastowen");
    auto s = create_sobol_sampler(SamplerContext{params, IVec2(32, 20), 0, 0});
    for (IVec2 pixel : {IVec2(0, 0), IVec2(31, 19), IVec2(12, 7)})
      for (int a = 0; a <= k; ++a) {
        std::set<std::pair<int, int>> cells;
        for (int j = 0; j < n; ++j) {
          s->start_pixel_sample(pixel, j);
          Vec2 u = s->get_pixel_2d();
          cells.insert({int(double(u.x) * (1 << a)), int(double(u.y) * (1 << (k - a)))});
        }
        EXPECT_EQ(int(cells.size()), n) << "k " << k << " a " << a;
      }
  }
}

TEST(SobolSampler, DimensionsPastTheMatricesArePaddedDeterministically) {
  ParameterList params = sobol_params(16, "");
  auto s = create_sobol_sampler(SamplerContext{params, IVec2(8, 8), 0, 0});
  s->start_pixel_sample(IVec2(2, 3), 5, kSobolDimensions - 1);
  float last = s->get_1d();
  float padded = s->get_1d();
  Vec2 more = s->get_2d();
  s->start_pixel_sample(IVec2(2, 3), 5, kSobolDimensions);
  EXPECT_EQ(s->get_1d(), padded);
  EXPECT_EQ(s->get_2d(), more);
  EXPECT_TRUE(last >= 0.f && last < 1.f && padded >= 0.f && padded < 1.f);
}

TEST(SobolSampler, FactoryReadsPbrtParameters) {
  ParameterList defaults;
  auto s = create_sobol_sampler(SamplerContext{defaults, IVec2(8, 8), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 16);
  EXPECT_NE(s->to_string().find("randomization=fastowen"), std::string::npos) << s->to_string();
  ParameterList p = sobol_params(12, "owen");
  auto t = create_sobol_sampler(SamplerContext{p, IVec2(8, 8), 0, 0});  // not a power of two: a warning only
  EXPECT_EQ(t->samples_per_pixel(), 12);
  auto u = create_sobol_sampler(SamplerContext{p, IVec2(8, 8), 32, 0});
  EXPECT_EQ(u->samples_per_pixel(), 32);
  ParameterList bad = sobol_params(0, "");
  EXPECT_THROW(create_sobol_sampler(SamplerContext{bad, IVec2(8, 8), 0, 0}), SceneError);
  ParameterList bad_r = sobol_params(16, "fast-owen");
  EXPECT_THROW(create_sobol_sampler(SamplerContext{bad_r, IVec2(8, 8), 0, 0}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
