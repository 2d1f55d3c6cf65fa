// The void-and-cluster textures behind the pmj02bn sampler's per-pixel rotations: each is a
// permutation of its ranks (so its values are uniform), it tiles the plane, and it is blue
// noise: its power spectrum is low at low frequencies, where white noise's is flat.
#include "samplers/blue_noise.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <complex>
#include <numbers>

#include "samplers/hash.h"
#include "samplers/pmj02bn_tables.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Mean power of the (mean-removed) values' 2-D DFT over the frequencies of radius 1 to 8
// cycles per texture, divided by the mean power over all non-zero frequencies (which
// Parseval gives from the variance): about 1 for white noise at any frequency.
double low_frequency_power_ratio(const std::vector<double>& v, int size) {
  double mean = 0, sum2 = 0;
  for (double x : v) mean += x / double(v.size());
  for (double x : v) sum2 += (x - mean) * (x - mean);
  const double n = double(v.size()), mean_power = n * sum2 / (n - 1);
  double low = 0;
  int bins = 0;
  for (int fy = -8; fy <= 8; ++fy)
    for (int fx = -8; fx <= 8; ++fx) {
      const int r2 = fx * fx + fy * fy;
      if (r2 < 1 || r2 > 64) continue;
      std::complex<double> s = 0;
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
          s += (v[size_t(y * size + x)] - mean) * std::polar(1.0, -2 * std::numbers::pi * (fx * x + fy * y) / size);
      low += std::norm(s);
      ++bins;
    }
  return low / bins / mean_power;
}

TEST(BlueNoise, ATextureIsAPermutationOfItsRanks) {
  const std::vector<uint16_t> r = make_void_and_cluster(64, 3);
  std::vector<int> count(64 * 64, 0);
  for (uint16_t v : r) ++count[v];
  for (int c : count) ASSERT_EQ(c, 1);
}

TEST(BlueNoise, LowFrequenciesHoldLittlePowerUnlikeWhiteNoise) {
  std::vector<double> blue, white;
  for (int y = 0; y < kBlueNoiseSize; ++y)
    for (int x = 0; x < kBlueNoiseSize; ++x) {
      blue.push_back(blue_noise(5, IVec2(x, y)));
      white.push_back(hash_float(x, y, 5));
    }
  // 196 frequencies, half of them independent (a real signal's spectrum is symmetric): white
  // noise's ratio is 1 with a standard deviation of about 0.1, so [0.6, 1.4] is 4 sigma.
  const double w = low_frequency_power_ratio(white, kBlueNoiseSize);
  EXPECT_GT(w, 0.6);
  EXPECT_LT(w, 1.4);
  // Measured 1e-4 for void-and-cluster with sigma 1.5; 0.02 is 50 times white noise's floor.
  EXPECT_LT(low_frequency_power_ratio(blue, kBlueNoiseSize), 0.02);
}

TEST(BlueNoise, TexturesTileAndDiffer) {
  for (IVec2 p : {IVec2(0, 0), IVec2(17, 100), IVec2(127, 3)}) {
    const float v = blue_noise(2, p);
    EXPECT_GT(v, 0.f);
    EXPECT_LT(v, 1.f);
    EXPECT_EQ(v, blue_noise(2, IVec2(p.x + kBlueNoiseSize, p.y - 3 * kBlueNoiseSize)));
    EXPECT_EQ(v, blue_noise(2 + kBlueNoiseTextures, p));
  }
  int same = 0;
  for (int x = 0; x < kBlueNoiseSize; ++x) same += blue_noise(0, IVec2(x, 9)) == blue_noise(1, IVec2(x, 9));
  EXPECT_LT(same, 4);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
