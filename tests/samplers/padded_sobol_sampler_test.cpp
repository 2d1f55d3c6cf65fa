// The "paddedsobol" sampler: every 1-D and 2-D sample of a pixel, over its samples-per-pixel
// samples, is a (0,2) point set in base 2 (one point in each elementary interval of volume
// 1/spp: the stratification Sobol' padding gives, checked directly), for any randomisation;
// successive dimensions are shuffled independently (their sample orders differ); and a count
// that is not a power of two warns, as pbrt-v4's does.
#include <gtest/gtest.h>

#include <set>

#include "../support/unity_id.h"
#include "core/error.h"
#include "samplers/padded_sobol_sampler.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

PaddedSobolSampler sampler(int spp, Randomization r) { return PaddedSobolSampler(spp, r, 11); }

// Whether the points are one in each of the spp elementary 2-D intervals of every shape
// 2^-a x 2^-(m-a), spp = 2^m.
bool is_02_net(const std::vector<Vec2>& p, int m) {
  for (int a = 0; a <= m; ++a) {
    std::set<std::pair<int, int>> cells;
    for (const Vec2& q : p) cells.insert({int(q.x * float(1 << a)), int(q.y * float(1 << (m - a)))});
    if (cells.size() != p.size()) return false;
  }
  return true;
}

TEST(PaddedSobolSampler, EveryDimensionPairOfAPixelIsA02Net) {
  for (Randomization r :
       {Randomization::None, Randomization::PermuteDigits, Randomization::FastOwen, Randomization::Owen}) {
    const int m = 6, spp = 1 << m;
    PaddedSobolSampler s = sampler(spp, r);
    for (IVec2 pixel : {IVec2(0, 0), IVec2(37, 5)}) {
      std::vector<std::vector<Vec2>> dims(4);
      std::vector<std::vector<float>> ones(2);
      for (int i = 0; i < spp; ++i) {
        s.start_pixel_sample(pixel, i);
        dims[0].push_back(s.get_pixel_2d());
        ones[0].push_back(s.get_1d());
        dims[1].push_back(s.get_2d());
        dims[2].push_back(s.get_2d());
        ones[1].push_back(s.get_1d());
        dims[3].push_back(s.get_2d());
      }
      for (const auto& d : dims) EXPECT_TRUE(is_02_net(d, m)) << randomization_name(r);
      for (const auto& o : ones) {
        std::set<int> strata;
        for (float v : o) strata.insert(int(v * spp));
        EXPECT_EQ(int(strata.size()), spp) << randomization_name(r);
      }
      // Dimensions are padded, not joined: the pairs' sample orders are shuffled independently.
      if (r != Randomization::None) {
        int same = 0;
        for (int i = 0; i < spp; ++i) same += int(dims[1][i].x * spp) == int(dims[2][i].x * spp);
        EXPECT_LT(same, spp / 4);
      }
    }
  }
}

TEST(PaddedSobolSampler, ANonPowerOfTwoCountWarns) {
  ParameterList params(SourceLoc{"s.pbrt", 4, 1});
  Param n;
  n.type = "integer";
  n.name = "pixelsamples";
  n.numbers = {24};
  params.add(n);
  const int before = warning_count();
  auto s = create_paddedsobol_sampler(SamplerContext{params, IVec2(16, 16), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 24);
  EXPECT_EQ(warning_count(), before + 1);
  EXPECT_FALSE(s->progressive());
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
