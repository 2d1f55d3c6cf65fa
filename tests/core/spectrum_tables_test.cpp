// The tables read at every wavelength of every sample. interpolate_spectrum finds its segment by
// binary search; it must give, bit for bit, what the plain linear scan below gives (the
// definition: piecewise linear through the points, constant beyond the ends), at the points
// themselves, next to them, between them and outside. The white illuminant's table, which the
// compiler computes, must be D65 over its luminance as spectrum_to_xyz computes it at run time.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "../support/unity_id.h"
#include "core/named_spectra.h"
#include "core/spectrum.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// The reference: walk the points until the next one is not below l.
float linear_scan(const std::vector<float>& lambda, const std::vector<float>& value, float l) {
  const size_t n = std::min(lambda.size(), value.size());
  if (n == 0) return 0.f;
  if (n == 1 || l <= lambda[0]) return value[0];
  if (l >= lambda[n - 1]) return value[n - 1];
  size_t j = 0;
  while (lambda[j + 1] < l) ++j;
  const float t = (l - lambda[j]) / (lambda[j + 1] - lambda[j]);
  return (1.f - t) * value[j] + t * value[j + 1];
}

void expect_same(const std::vector<float>& lambda, const std::vector<float>& value, float l) {
  const float want = linear_scan(lambda, value, l), got = interpolate_spectrum(lambda, value, l);
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << "at " << l;
  } else {
    EXPECT_EQ(std::bit_cast<uint32_t>(got), std::bit_cast<uint32_t>(want))
        << "at " << l << ": " << got << " vs " << want;
  }
}

// Wavelengths that probe every branch: the points, one float either side of each, the
// midpoints, far outside, infinities, NaN, and many uniform random ones over the range.
std::vector<float> probes(const std::vector<float>& lambda, std::mt19937& rng) {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> l = {-inf, inf, std::numeric_limits<float>::quiet_NaN(), 0.f, -1.f, 1e6f};
  for (size_t i = 0; i < lambda.size(); ++i) {
    l.push_back(lambda[i]);
    l.push_back(std::nextafter(lambda[i], -inf));
    l.push_back(std::nextafter(lambda[i], inf));
    if (i + 1 < lambda.size()) l.push_back(0.5f * (lambda[i] + lambda[i + 1]));
  }
  std::uniform_real_distribution<float> u(lambda.front() - 20.f, lambda.back() + 20.f);
  for (int k = 0; k < 20000; ++k) l.push_back(u(rng));
  return l;
}

TEST(InterpolateSpectrum, MatchesTheLinearScanBitForBit) {
  std::mt19937 rng(14);
  // Random tables: 1 to 600 points, irregular increasing wavelengths, values of both signs.
  for (int table = 0; table < 40; ++table) {
    const int n = table == 0 ? 1 : table == 1 ? 2 : 1 + int(rng() % 600);
    std::vector<float> lambda, value;
    float l = 300.f + float(rng() % 100);
    for (int i = 0; i < n; ++i) {
      l += std::uniform_real_distribution<float>(0.01f, 5.f)(rng);
      lambda.push_back(l);
      value.push_back(std::uniform_real_distribution<float>(-2.f, 5.f)(rng));
    }
    for (float x : probes(lambda, rng)) expect_same(lambda, value, x);
  }
  // Every named tabulated spectrum (metals, glasses, illuminants), read as eyetrace reads them.
  for (const std::string& name : named_spectrum_names()) {
    const NamedSpectrum& s = *find_named_spectrum(name);
    if (s.analytic) continue;
    std::vector<float> lambda, value;
    for (size_t i = 0; i + 1 < s.interleaved.size(); i += 2) {
      lambda.push_back(s.interleaved[i]);
      value.push_back(s.interleaved[i + 1]);
    }
    for (float x : probes(lambda, rng)) expect_same(lambda, value, x);
  }
}

TEST(WhiteIlluminant, IsD65OverItsLuminanceBitForBit) {
  SpectrumSamples d65{};
  for (int i = 0; i < kCieRows; ++i) d65[i] = cie_table()[i].d65;
  const float y = spectrum_to_xyz(d65).y;
  for (int i = 0; i < kCieRows; ++i) {
    EXPECT_EQ(kCieWhite[i], d65[i] / y) << cie_table()[i].lambda_nm << " nm";
    EXPECT_EQ(white_illuminant(cie_table()[i].lambda_nm), d65[i] / y) << cie_table()[i].lambda_nm << " nm";
  }
  // Between rows, linear; outside the table, nothing.
  EXPECT_FLOAT_EQ(white_illuminant(557.5f), 0.5f * (kCieWhite[35] + kCieWhite[36]));
  EXPECT_EQ(white_illuminant(379.f), 0.f);
  EXPECT_EQ(white_illuminant(781.f), 0.f);
}

TEST(InterpolateSpectrum, EmptyTableIsZero) { EXPECT_EQ(interpolate_spectrum({}, {}, 550.f), 0.f); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
