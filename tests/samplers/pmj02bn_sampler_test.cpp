// The "pmj02bn" sampler and its point sets, against the definitions: every prefix of 2^m points
// of every set is a (0,m,2)-net (one point in each elementary interval of area 2^-m, all 17
// shapes up to m = 16), and later blocks of 2^m points too; the sets differ; each pixel's film positions are a
// (0,m,2)-net of the pixel and the pixels of a tile use each of the set's points once; a 1-D dimension puts one sample
// in each of the pixel's spp strata.
#include "samplers/pmj02bn_sampler.h"

#include <gtest/gtest.h>

#include <bit>
#include <set>

#include "../support/params.h"
#include "core/error.h"
#include "samplers/pmj02bn_points.h"

namespace eyetrace {
namespace {

using Points = std::vector<std::array<uint32_t, 2>>;

// Whether points [begin, begin + 2^m) are one in each elementary interval of every shape
// 2^-a x 2^-(m-a), read from the fixed-point digits.
bool is_02_net(const Points& p, size_t begin, int m) {
  const size_t n = size_t(1) << m;
  for (int a = 0; a <= m; ++a) {
    std::vector<uint8_t> seen(n, 0);
    for (size_t i = begin; i < begin + n; ++i) {
      const uint64_t x = a == 0 ? 0 : p[i][0] >> (32 - a), y = m - a == 0 ? 0 : p[i][1] >> (32 - (m - a));
      uint8_t& s = seen[(x << (m - a)) | y];
      if (s) return false;
      s = 1;
    }
  }
  return true;
}

TEST(Pmj02bnPoints, EveryPrefixOfEverySetIsA02Net) {
  for (int set = 0; set < kPmj02bnSets; ++set) {
    const Points& p = pmj02bn_set(set);
    ASSERT_EQ(p.size(), kPmj02bnPoints);
    for (int m = 0; m <= kPmj02bnLevels; ++m) EXPECT_TRUE(is_02_net(p, 0, m)) << "set " << set << ", m " << m;
    // A (0,2)-sequence: the later blocks of 2^m points are nets too.
    for (int m : {2, 5, 8}) EXPECT_TRUE(is_02_net(p, size_t(7) << m, m)) << "set " << set << ", m " << m;
    if (set > 0) EXPECT_NE(p[1], pmj02bn_set(set - 1)[1]) << set;  // independently scrambled
  }
  // The check can fail: swapping two points' x between strata breaks the nets.
  Points broken = pmj02bn_set(0);
  broken[1][0] = broken[0][0];
  EXPECT_FALSE(is_02_net(broken, 0, 2));
}

TEST(Pmj02bnSampler, APixelsPositionsAreANetAndATileUsesEveryPointOnce) {
  for (int spp : {16, 64}) {
    Pmj02bnSampler s(spp, 3);
    const int tile = s.pixel_tile_size();
    EXPECT_EQ(tile * tile * spp, int(kPmj02bnPoints));
    const int m = std::countr_zero(unsigned(spp));
    std::set<std::pair<float, float>> all;
    for (int py = 0; py < tile; ++py)
      for (int px = 0; px < tile; ++px) {
        Points cell;
        for (int i = 0; i < spp; ++i) {
          s.start_pixel_sample(IVec2(px, py), i);
          const Vec2 u = s.get_pixel_2d();
          ASSERT_TRUE(u.x >= 0.f && u.x < 1.f && u.y >= 0.f && u.y < 1.f);
          cell.push_back({uint32_t(double(u.x) * 0x1p32), uint32_t(double(u.y) * 0x1p32)});
          all.insert({(float(px) + u.x) / float(tile), (float(py) + u.y) / float(tile)});
        }
        if ((px * 7 + py) % 97 == 0) EXPECT_TRUE(is_02_net(cell, 0, m)) << spp << " " << px << "," << py;
      }
    EXPECT_EQ(all.size(), size_t(kPmj02bnPoints)) << spp;
    // The tile repeats, also for negative pixel coordinates.
    s.start_pixel_sample(IVec2(1, 2), 5);
    const Vec2 a = s.get_pixel_2d();
    s.start_pixel_sample(IVec2(1 - tile, 2 + 3 * tile), 5);
    EXPECT_EQ(a, s.get_pixel_2d());
  }
}

TEST(Pmj02bnSampler, OneDimensionalSamplesFillThePixelsStrata) {
  const int spp = 64;
  Pmj02bnSampler s(spp, 5);
  for (IVec2 pixel : {IVec2(0, 0), IVec2(33, 9)}) {
    std::vector<std::set<int>> strata(3);
    for (int i = 0; i < spp; ++i) {
      s.start_pixel_sample(pixel, i);
      for (auto& st : strata) st.insert(int(s.get_1d() * spp));
    }
    for (const auto& st : strata) EXPECT_EQ(int(st.size()), spp);
  }
}

TEST(Pmj02bnSampler, TooManySamplesIsAnErrorNamingTheParameter) {
  ParameterList pl(SourceLoc{"scene.pbrt", 4, 1});
  Param p = test::number_param("integer", "pixelsamples", {65536 * 4});
  p.loc = SourceLoc{"scene.pbrt", 4, 20};
  pl.add(p);
  std::string e;
  try {
    create_pmj02bn_sampler(SamplerContext{pl, IVec2(8, 8), 0, 0});
  } catch (const SceneError& err) {
    e = err.what();
  }
  EXPECT_NE(e.find("scene.pbrt:4"), std::string::npos) << e;
  EXPECT_NE(e.find("pixelsamples"), std::string::npos) << e;
}

}  // namespace
}  // namespace eyetrace
