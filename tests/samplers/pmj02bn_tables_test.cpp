// The embedded pmj02bn tables are what the generators make (so the properties the generator
// tests establish hold for the sampler's data) and are read with the documented indexing.
#include "samplers/pmj02bn_tables.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(Pmj02bnTables, PointSetIsTheGeneratorsOutput) {
  const int set = 3;
  const Pmj02Points p = make_pmj02_points(kPmj02bnPoints, kPmj02bnSeed + set, kPmj02bnCandidates);
  size_t differ = 0;
  for (uint32_t i = 0; i < kPmj02bnPoints; ++i) differ += p[i] != pmj02bn_point(set, i);
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(pmj02bn_point(set + kPmj02bnSets, 77), p[77]);  // sets wrap
}

TEST(Pmj02bnTables, TexturesAreTheGeneratorsOutput) {
  for (int t : {0, kBlueNoiseTextures - 1}) {
    const std::vector<uint16_t> r = make_void_and_cluster(kBlueNoiseSize, kBlueNoiseSeed + uint64_t(t));
    size_t differ = 0;
    for (int y = 0; y < kBlueNoiseSize; ++y)
      for (int x = 0; x < kBlueNoiseSize; ++x) {
        const uint16_t rank = r[size_t(y) * kBlueNoiseSize + size_t(x)];
        differ += rank != blue_noise_rank(t, x, y);
        differ += blue_noise(t, IVec2(x, y)) != (float(rank) + 0.5f) / (kBlueNoiseSize * kBlueNoiseSize);
      }
    EXPECT_EQ(differ, 0u) << "texture " << t;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
