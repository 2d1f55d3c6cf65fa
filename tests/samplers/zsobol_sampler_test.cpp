// The ZSobol sampler: a pixel's 2^k samples are an aligned block of Sobol' indices, so in every
// dimension they form a (0,k,2)-net (each sample alone in every elementary interval), for every
// randomisation; its index shuffle is a bijection over the image; pbrt-v4's parameters.
#include "samplers/zsobol_sampler.h"
#include "../support/unity_id.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

ParameterList zsobol_params(int spp, const std::string& randomization) {
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

// The samples' cells for the elementary intervals 2^-a x 2^-(k-a): all distinct in a net.
bool is_02_net(const std::vector<Vec2>& pts, int k) {
  for (int a = 0; a <= k; ++a) {
    std::set<std::pair<int, int>> cells;
    for (Vec2 p : pts) cells.insert({int(double(p.x) * (1 << a)), int(double(p.y) * (1 << (k - a)))});
    if (cells.size() != pts.size()) return false;
  }
  return true;
}

TEST(ZSobolSampler, PixelSamplesAreNetsInEveryDimension) {
  for (const char* r : {"none", "permutedigits", "fastowen", "owen"})
    for (int k : {4, 5, 6}) {
      int n = 1 << k;
      ParameterList params = zsobol_params(n, r);
      auto s = create_zsobol_sampler(SamplerContext{params, IVec2(20, 13), 0, 5});
      ASSERT_EQ(s->samples_per_pixel(), n);
      for (IVec2 pixel : {IVec2(0, 0), IVec2(7, 3), IVec2(19, 12)}) {
        const int n_1d = 4, n_2d = 4;
        std::vector<std::vector<float>> dims_1d(n_1d);
        std::vector<std::vector<Vec2>> dims_2d(n_2d);
        for (int i = 0; i < n; ++i) {
          s->start_pixel_sample(pixel, i);
          dims_2d[0].push_back(s->get_pixel_2d());
          for (int d = 0; d < n_1d; ++d) dims_1d[size_t(d)].push_back(s->get_1d());
          for (int d = 1; d < n_2d; ++d) dims_2d[size_t(d)].push_back(s->get_2d());
        }
        for (const auto& values : dims_1d) {
          std::set<int> strata;
          for (float u : values) strata.insert(int(double(u) * n));
          EXPECT_EQ(int(strata.size()), n) << r << " k " << k;
        }
        for (const auto& pts : dims_2d) EXPECT_TRUE(is_02_net(pts, k)) << r << " k " << k;
      }
    }
}

TEST(ZSobolSampler, IndexShuffleIsABijectionOverTheImage) {
  // 4 x 4 pixels with 8 samples: the shuffled indices of one dimension are exactly 0..127.
  ZSobolSampler s(8, IVec2(4, 4), Randomization::FastOwen, 0);
  for (int dim : {0, 1, 6}) {
    std::set<uint64_t> indices;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        for (int i = 0; i < 8; ++i) {
          s.start_pixel_sample(IVec2(x, y), i, dim);
          indices.insert(s.sample_index());
        }
    ASSERT_EQ(indices.size(), 128u);
    EXPECT_EQ(*indices.rbegin(), 127u);
  }
}

TEST(ZSobolSampler, DifferentDimensionsUseDifferentIndices) {
  ZSobolSampler s(16, IVec2(8, 8), Randomization::None, 0);
  int differ = 0;
  for (int i = 0; i < 16; ++i) {
    s.start_pixel_sample(IVec2(3, 3), i, 0);
    uint64_t a = s.sample_index();
    s.start_pixel_sample(IVec2(3, 3), i, 1);
    differ += s.sample_index() != a;
  }
  EXPECT_GT(differ, 0);
}

TEST(ZSobolSampler, RoundsSampleCountsUpToPowersOfTwo) {
  ParameterList params = zsobol_params(10, "");
  auto s = create_zsobol_sampler(SamplerContext{params, IVec2(8, 8), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 16);
  auto t = create_zsobol_sampler(SamplerContext{params, IVec2(8, 8), 64, 0});
  EXPECT_EQ(t->samples_per_pixel(), 64);
}

TEST(ZSobolSampler, DefaultsAreSixteenSamplesFastOwen) {
  ParameterList params;
  auto s = create_zsobol_sampler(SamplerContext{params, IVec2(8, 8), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 16);
  EXPECT_NE(s->to_string().find("randomization=fastowen"), std::string::npos) << s->to_string();
}

TEST(ZSobolSampler, RejectsBadParameters) {
  ParameterList bad_r = zsobol_params(16, "scrambled");
  EXPECT_THROW(create_zsobol_sampler(SamplerContext{bad_r, IVec2(8, 8), 0, 0}), SceneError);
  for (int spp : {0, -4, (1 << 24) + 1}) {
    ParameterList bad_n = zsobol_params(spp, "");
    EXPECT_THROW(create_zsobol_sampler(SamplerContext{bad_n, IVec2(8, 8), 0, 0}), SceneError) << spp;
  }
  ParameterList ok = zsobol_params(16, "");
  EXPECT_THROW(create_zsobol_sampler(SamplerContext{ok, IVec2(8, 8), (1 << 24) + 1, 0}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// The sampler caches per-pixel work; values must not depend on the order of queries. A sampler
// that jumps between pixels, samples and dimensions (some past the cache) must return exactly
// what a fresh sampler returns for each query.
TEST(ZSobolSampler, ValuesIndependentOfQueryOrder) {
  for (int spp : {1, 2, 8, 16, 32}) {
    ZSobolSampler shared(spp, IVec2(37, 21), Randomization::FastOwen, 7);
    std::mt19937 rng{uint32_t(spp)};
    for (int q = 0; q < 2000; ++q) {
      const IVec2 pixel(int(rng() % 37), int(rng() % 21));
      const int index = int(rng() % uint32_t(spp)), dim = int(rng() % 80);
      ZSobolSampler fresh(spp, IVec2(37, 21), Randomization::FastOwen, 7);
      shared.start_pixel_sample(pixel, index, dim);
      fresh.start_pixel_sample(pixel, index, dim);
      ASSERT_EQ(shared.get_2d(), fresh.get_2d()) << spp << " " << q;
      ASSERT_EQ(shared.get_1d(), fresh.get_1d()) << spp << " " << q;
    }
  }
}

// The order a splatting render takes, sample index outermost over tiles wider than the tile
// cache (pixels 16 apart share its slots): every value is a fresh sampler's.
TEST(ZSobolSampler, SampleIndexOutermostOrderGivesTheSameValues) {
  for (int spp : {4, 32}) {
    ZSobolSampler shared(spp, IVec2(70, 40), Randomization::FastOwen, 3);
    for (int index = 0; index < spp; ++index)
      for (int y = 3; y < 37; y += 2)
        for (int x = 0; x < 70; x += 3) {
          ZSobolSampler fresh(spp, IVec2(70, 40), Randomization::FastOwen, 3);
          shared.start_pixel_sample(IVec2(x, y), index, 0);
          fresh.start_pixel_sample(IVec2(x, y), index, 0);
          for (int d = 0; d < 10; ++d) {  // dimensions 0-19, past the tile cache's 16
            ASSERT_EQ(shared.get_2d(), fresh.get_2d()) << spp << " " << index << " " << x << " " << y << " " << d;
          }
        }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// A defocused edge couples film position and pupil: f = [x + u > 1] over (film x, lens u),
// mean 1/2 in every pixel. Joint lens dimensions stratify (x, u) together and must integrate it
// with clearly less error than pbrt-v4's padded dimensions. At 64 spp the measured RMS errors
// over 1024 pixels are 0.016 (joint) and 0.039 (padded); the test asks for a ratio < 0.75. (At
// 16 spp the two are alike for this edge: the gain appears from about 32 spp, as in the
// convergence harness.)
TEST(ZSobolSampler, JointLensDimensionsStratifyFilmAndPupilTogether) {
  auto rms_error = [](ZSobolSampler::LensDimensions lens) {
    const int spp = 64;
    ZSobolSampler s(spp, IVec2(32, 32), Randomization::FastOwen, 3, lens);
    double sum_sq = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        double mean = 0;
        for (int i = 0; i < spp; ++i) {
          s.start_pixel_sample(IVec2(x, y), i);
          const Vec2 film = s.get_pixel_2d(), lens_uv = s.get_2d();
          mean += (film.x + lens_uv.x > 1.f) ? 1.0 / spp : 0.0;
        }
        sum_sq += (mean - 0.5) * (mean - 0.5);
      }
    return std::sqrt(sum_sq / 1024);
  };
  const double joint = rms_error(ZSobolSampler::LensDimensions::Joint);
  const double padded = rms_error(ZSobolSampler::LensDimensions::Padded);
  EXPECT_LT(joint, 0.75 * padded) << "joint " << joint << " padded " << padded;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
