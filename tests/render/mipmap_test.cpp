// The image pyramid and pbrt-v4's texture filters (render/mipmap.h), against values computed
// here from the texels: level sizes and means (box averaging conserves the mean), bilinear and
// point lookups written out, trilinear as the blend of two levels, EWA weights that sum to one
// and see the mean of the image under a wide footprint, the Lanczos resize of a side that is not
// a power of two against the windowed sinc written out in double precision, 8-bit levels decoded
// as sRGB per texel, and wrap modes.
#include <gtest/gtest.h>

#include "../support/unity_id.h"

#include <cmath>
#include <numbers>
#include <random>

#include "render/mipmap.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Image random_image(int w, int h, int channels, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  Image im;
  im.width = w, im.height = h, im.channels = channels;
  im.pixels.resize(size_t(w) * h * channels);
  for (float& v : im.pixels) v = u(rng);
  return im;
}

double level_mean(const MipMap& m, int level, int c) {
  const IVec2 r = m.resolution(level);
  double s = 0;
  for (int y = 0; y < r.y; ++y)
    for (int x = 0; x < r.x; ++x) s += m.texel(level, x, y, c);
  return s / (double(r.x) * r.y);
}

// IEC 61966-2-1, written independently of the code under test.
double srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

TEST(MipMap, LevelsHalveDownToOneTexelAndKeepTheMean) {
  const Image im = random_image(16, 4, 3, 1);
  const MipMap m(im, 3, false, {}, MipWrap::Repeat);
  ASSERT_EQ(m.levels(), 5);  // 1 + log2(16), as pbrt-v4 counts them
  const IVec2 sizes[] = {{16, 4}, {8, 2}, {4, 1}, {2, 1}, {1, 1}};
  for (int l = 0; l < 5; ++l) {
    EXPECT_EQ(m.resolution(l), sizes[l]) << l;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(level_mean(m, l, c), level_mean(m, 0, c), 1e-6) << l;
  }
  // Level 1 texel (3, 1) is the mean of level 0's texels (6..7, 2..3).
  const double box = (im.at(6, 2, 1) + im.at(7, 2, 1) + im.at(6, 3, 1) + im.at(7, 3, 1)) / 4.0;
  EXPECT_NEAR(m.texel(1, 3, 1, 1), box, 1e-6);
}

TEST(MipMap, BilinearAndPointAtLevelZeroAsWrittenOut) {
  const Image im = random_image(8, 8, 1, 2);
  const MipMap m(im, 1, false, {}, MipWrap::Clamp);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.07f, 0.93f);  // away from the clamped border
  for (int i = 0; i < 200; ++i) {
    const Vec2 st(u(rng), u(rng));
    const double x = st.x * 8.0 - 0.5, y = st.y * 8.0 - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double dx = x - x0, dy = y - y0;
    const double want = (1 - dx) * (1 - dy) * im.at(x0, y0, 0) + dx * (1 - dy) * im.at(x0 + 1, y0, 0) +
                        (1 - dx) * dy * im.at(x0, y0 + 1, 0) + dx * dy * im.at(x0 + 1, y0 + 1, 0);
    float got = -1.f;
    m.filter(MipFilter::Bilinear, 8.f, st, Vec2(0.f), Vec2(0.f), &got);
    EXPECT_NEAR(got, want, 1e-5);
    m.filter(MipFilter::Point, 8.f, st, Vec2(0.f), Vec2(0.f), &got);
    EXPECT_EQ(got, im.at(int(st.x * 8.f), int(st.y * 8.f), 0));  // the texel the point lies in
  }
}

TEST(MipMap, FootprintPicksTheLevelAndTrilinearBlendsTwo) {
  const Image im = random_image(16, 16, 1, 4);
  const MipMap m(im, 1, false, {}, MipWrap::Repeat);
  const Vec2 st(0.37f, 0.61f);
  // pbrt-v4: width = 2 max|d|, level = (levels - 1) + log2(width). Width 2^-2.5: level 1.5.
  const float d = 0.5f * std::pow(2.f, -2.5f);
  float bilinear, trilinear, l1, l2;
  m.filter(MipFilter::Bilinear, 8.f, st, Vec2(d, 0.f), Vec2(0.f, d), &bilinear);
  m.filter(MipFilter::Trilinear, 8.f, st, Vec2(d, 0.f), Vec2(0.f, d), &trilinear);
  m.bilerp(1, st, &l1);
  m.bilerp(2, st, &l2);
  EXPECT_NEAR(bilinear, l1, 1e-6);
  EXPECT_NEAR(trilinear, 0.5f * (l1 + l2), 1e-5);
  // A footprint wider than the image returns the one-texel level: the mean.
  for (MipFilter f : {MipFilter::Point, MipFilter::Bilinear, MipFilter::Trilinear, MipFilter::Ewa}) {
    float wide;
    m.filter(f, 8.f, st, Vec2(3.f, 0.f), Vec2(0.f, 3.f), &wide);
    EXPECT_NEAR(wide, level_mean(m, 0, 0), 1e-5);
  }
}

TEST(MipMap, EwaWeightsSumToOneAndStayWithinTheTexels) {
  Image flat = random_image(32, 32, 3, 5);
  for (size_t i = 0; i < flat.pixels.size(); ++i) flat.pixels[i] = 0.25f + 0.25f * float(i % 3);
  const MipMap constant(flat, 3, false, {}, MipWrap::Black);
  const Image im = random_image(32, 32, 1, 6);
  const MipMap m(im, 1, false, {}, MipWrap::Repeat);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.2f, 0.8f), dd(-0.05f, 0.05f);
  for (int i = 0; i < 300; ++i) {
    const Vec2 st(u(rng), u(rng)), d0(dd(rng), dd(rng)), d1(dd(rng), dd(rng));
    float out[3];
    constant.filter(MipFilter::Ewa, 8.f, st, d0, d1, out);  // inside, black never reached
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], 0.25f + 0.25f * float(c), 1e-5);
    m.filter(MipFilter::Ewa, 4.f, st, d0, d1, out);
    EXPECT_TRUE(out[0] >= 0.f && out[0] <= 1.f);
  }
}

TEST(MipMap, NonPowerOfTwoSidesAreResizedWithTheWindowedSinc) {
  // One row of 3 texels resized to 4 (rows stay 1): pbrt-v4's Lanczos, radius 2, tau 2, four
  // taps from floor(centre - 2 + 0.5), normalised, clamp wrap beyond the edges, negatives to 0.
  Image im;
  im.width = 3, im.height = 1, im.channels = 1;
  im.pixels = {0.2f, 0.9f, 0.4f};
  const MipMap m(im, 1, false, {}, MipWrap::Clamp);
  ASSERT_EQ(m.resolution(0), IVec2(4, 1));
  auto sinc = [](double x) {
    return std::abs(x) < 1e-12 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
  };
  for (int i = 0; i < 4; ++i) {
    const double centre = (i + 0.5) * 3.0 / 4.0;
    const int first = int(std::floor(centre - 2.0 + 0.5));
    double sum = 0, wsum = 0;
    for (int j = 0; j < 4; ++j) {
      const double x = first + j + 0.5 - centre;
      const double w = std::abs(x) > 2 ? 0 : sinc(x) * sinc(x / 2);
      sum += w * im.pixels[size_t(std::clamp(first + j, 0, 2))];
      wsum += w;
    }
    EXPECT_NEAR(m.texel(0, i, 0, 0), std::max(0.0, sum / wsum), 1e-6) << i;
  }
  // A constant stays constant (the weights are normalised).
  Image grey = random_image(24, 12, 1, 8);
  for (float& v : grey.pixels) v = 0.3f;
  const MipMap g(grey, 1, false, {}, MipWrap::Repeat);
  EXPECT_EQ(g.resolution(0), IVec2(32, 16));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) EXPECT_NEAR(g.texel(0, x, y, 0), 0.3f, 1e-6);
}

TEST(MipMap, EightBitTexelsAreDecodedBeforeFiltering) {
  // 2 x 1 sRGB bytes 0 and 255: level 0 decodes each byte; the bilinear value halfway is the
  // mean of the decoded values (0.5), not the decoded mean of the bytes (0.214); the level
  // above holds 0.5 re-encoded to the nearest byte.
  Image im;
  im.width = 2, im.height = 1, im.channels = 1;
  im.pixels = {0.f, 1.f};
  const MipMap m(im, 1, true, {TexelEncoding::Kind::SRGB, 1.f}, MipWrap::Clamp);
  float mid;
  m.bilerp(0, Vec2(0.5f, 0.5f), &mid);
  EXPECT_NEAR(mid, 0.5f, 1e-6);
  const double byte = std::round(255.0 * (1.055 * std::pow(0.5, 1 / 2.4) - 0.055));  // sRGB encode of 0.5
  EXPECT_NEAR(m.texel(1, 0, 0, 0), srgb_decode(byte / 255.0), 1e-6);
  // Every byte of level 0 reads back as its decoded value.
  Image ramp;
  ramp.width = 256, ramp.height = 1, ramp.channels = 1;
  for (int i = 0; i < 256; ++i) ramp.pixels.push_back(float(i) / 255.f);
  const MipMap r(ramp, 1, true, {TexelEncoding::Kind::SRGB, 1.f}, MipWrap::Clamp);
  for (int i = 0; i < 256; ++i) EXPECT_NEAR(r.texel(0, i, 0, 0), srgb_decode(i / 255.0), 1e-6) << i;
  const MipMap gamma(ramp, 1, true, {TexelEncoding::Kind::Gamma, 2.f}, MipWrap::Clamp);
  EXPECT_NEAR(gamma.texel(0, 51, 0, 0), 0.04f, 1e-6);  // (51/255)^2
  EXPECT_LT(r.bytes(), 2 * 256u);                      // bytes, not floats
}

TEST(MipMap, BytesGiveTheTexelsOfTheSameImageAsFloats) {
  // An 8-bit PNG's bytes go straight to the pyramid; the same values given as floats k / 255
  // (another reader's) must build the same levels, for sides that are and are not powers of two.
  for (IVec2 size : {IVec2(8, 4), IVec2(6, 5), IVec2(1, 1)}) {
    std::mt19937 rng(uint32_t(size.x * 10 + size.y));
    std::vector<uint8_t> bytes(size_t(size.x) * size.y * 3);
    for (uint8_t& b : bytes) b = uint8_t(rng() & 0xff);
    Image im;
    im.width = size.x, im.height = size.y, im.channels = 3;
    for (uint8_t b : bytes) im.pixels.push_back(float(b) / 255.f);
    const TexelEncoding srgb{TexelEncoding::Kind::SRGB, 1.f};
    const MipMap from_bytes(bytes, size.x, size.y, 3, 3, srgb, MipWrap::Repeat);
    const MipMap from_floats(im, 3, true, srgb, MipWrap::Repeat);
    ASSERT_EQ(from_bytes.levels(), from_floats.levels());
    for (int l = 0; l < from_bytes.levels(); ++l) {
      const IVec2 r = from_bytes.resolution(l);
      ASSERT_EQ(r, from_floats.resolution(l));
      for (int y = 0; y < r.y; ++y)
        for (int x = 0; x < r.x; ++x)
          for (int c = 0; c < 3; ++c) ASSERT_EQ(from_bytes.texel(l, x, y, c), from_floats.texel(l, x, y, c));
    }
    if (size == IVec2(8, 4))  // level 0 is the bytes themselves
      EXPECT_NEAR(from_bytes.texel(0, 5, 2, 1), srgb_decode(bytes[(2 * 8 + 5) * 3 + 1] / 255.0), 1e-6);
  }
}

TEST(MipMap, WrapModesAndHostileCoordinates) {
  const Image im = random_image(4, 4, 1, 9);
  const MipMap repeat(im, 1, false, {}, MipWrap::Repeat), clamp(im, 1, false, {}, MipWrap::Clamp),
      black(im, 1, false, {}, MipWrap::Black);
  EXPECT_EQ(repeat.texel(0, -1, 5, 0), im.at(3, 1, 0));
  EXPECT_EQ(clamp.texel(0, -1, 5, 0), im.at(0, 3, 0));
  EXPECT_EQ(black.texel(0, -1, 5, 0), 0.f);
  float a, b;
  repeat.filter(MipFilter::Bilinear, 8.f, Vec2(0.3f, 0.6f), Vec2(0.f), Vec2(0.f), &a);
  repeat.filter(MipFilter::Bilinear, 8.f, Vec2(1000.3f, -99.4f), Vec2(0.f), Vec2(0.f), &b);
  EXPECT_NEAR(a, b, 1e-3);  // periodic
  const float nan = std::nanf(""), inf = INFINITY;
  for (MipFilter f : {MipFilter::Point, MipFilter::Bilinear, MipFilter::Trilinear, MipFilter::Ewa})
    for (const MipMap* map : {&repeat, &clamp, &black}) {
      for (Vec2 st : {Vec2(nan, 0.5f), Vec2(inf, 0.f), Vec2(1e30f, -1e30f)})
        for (Vec2 d : {Vec2(0.f), Vec2(nan), Vec2(inf, 0.f), Vec2(1e30f)}) {
          float out = -1.f;
          map->filter(f, 8.f, st, d, Vec2(0.f, d.x), &out);
          EXPECT_TRUE(std::isfinite(out) && out >= 0.f);
        }
    }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
