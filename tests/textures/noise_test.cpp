// Perlin noise and pbrt-v4's noise textures: noise is 0 at every lattice point and has period
// 256, its values stay within [-1, 1] and average 0, and it is continuous;
// fbm and turbulence are the stated sums; a polka dot is a disc of radius 0.35 (its area
// fraction of a cell pi 0.35^2 within 4 sigma) and half the cells, about, have one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "../support/unity_id.h"
#include "core/transform.h"
#include "scene/texture_store.h"
#include "textures/dots_texture.h"
#include "textures/marble_texture.h"
#include "textures/noise_textures.h"
#include "textures/perlin_noise.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(PerlinNoise, ZeroAtLatticePointsAndPeriodic) {
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> cell(-300, 300);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 2000; ++i) {
    const float x = float(cell(rng)), y = float(cell(rng)), z = float(cell(rng));
    EXPECT_EQ(perlin_noise(x, y, z), 0.f);
    const Vec3 p(x + u(rng), y + u(rng), z + u(rng));
    EXPECT_NEAR(perlin_noise(p), perlin_noise(p + Vec3(256.f, -512.f, 256.f)), 1e-4f);
  }
}

TEST(PerlinNoise, BoundedWithZeroMeanAndContinuous) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-100.f, 100.f);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  std::set<int> signs;
  for (int i = 0; i < n; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const float v = perlin_noise(p);
    ASSERT_LE(std::abs(v), 1.f) << p.x << " " << p.y << " " << p.z;
    sum += v;
    sum2 += double(v) * v;
    // Continuity: each corner term has slope at most |gradient| = sqrt 2 and the fade's slope is
    // at most 15/8, so a step of 1e-3 moves the value by well under 0.02.
    ASSERT_LT(std::abs(perlin_noise(p + Vec3(1e-3f, 0, 0)) - v), 0.02f);
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  // Points 200 apart on average in a 200-wide box: nearly independent; 4 sigma.
  EXPECT_NEAR(mean, 0.0, 4 * sd / std::sqrt(double(n)));
  EXPECT_GT(sd, 0.1);  // not the zero function
}

TEST(PerlinNoise, FbmAndTurbulenceAreTheStatedSums) {
  const Vec3 p(1.3f, -2.7f, 0.45f);
  EXPECT_EQ(fbm(p, 0.5f, 1), perlin_noise(p));
  EXPECT_FLOAT_EQ(fbm(p, 0.7f, 2), perlin_noise(p) + 0.7f * perlin_noise(1.99f * p));
  EXPECT_FLOAT_EQ(turbulence(p, 0.7f, 2),
                  std::abs(perlin_noise(p)) + 0.7f * std::abs(perlin_noise(1.99f * p)) + 0.49f * 0.2f);
  // The textures: "fbm" with octaves 3 and roughness 0.25 at a texture-space point.
  ParameterList params;
  Param o;
  o.type = "integer";
  o.name = "octaves";
  o.numbers = {3};
  params.add(o);
  Param r;
  r.type = "float";
  r.name = "roughness";
  r.numbers = {0.25};
  params.add(r);
  TextureStore store;
  TextureEvalContext c;
  c.p = p;
  EXPECT_FLOAT_EQ(create_fbm_texture(TextureContext{params, Transform(), store, ""})->evaluate(c), fbm(p, 0.25f, 3));
  EXPECT_FLOAT_EQ(create_wrinkled_texture(TextureContext{params, Transform(), store, ""})->evaluate(c),
                  turbulence(p, 0.25f, 3));
  ParameterList none;
  EXPECT_FLOAT_EQ(create_windy_texture(TextureContext{none, Transform(), store, ""})->evaluate(c),
                  std::abs(fbm(0.1f * p, 0.5f, 3)) * fbm(p, 0.5f, 6));
}

TEST(PolkaDots, EachDotIsADiscOfRadius035) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  const double disc = kPiDouble * 0.35 * 0.35;
  int with_dot = 0;
  const int cells = 400, per_cell = 4000;
  for (int c = 0; c < cells; ++c) {
    const float s0 = float(c % 20) * 7.f, t0 = float(c / 20) * 3.f;
    int inside = 0;
    for (int i = 0; i < per_cell; ++i) inside += inside_polka_dot(Vec2(s0 + u(rng), t0 + u(rng)));
    if (inside == 0) continue;
    ++with_dot;
    const double sigma = std::sqrt(disc * (1 - disc) / per_cell);
    EXPECT_NEAR(double(inside) / per_cell, disc, 4.5 * sigma) << "cell " << s0 << " " << t0;
  }
  // A cell has a dot where the noise at its centre-plus-half is positive: about half of them.
  EXPECT_GT(with_dot, cells / 4);
  EXPECT_LT(with_dot, 3 * cells / 4);
}

// pbrt-v4's marble spline: six cubic Bezier segments over nine overlapping control points,
// times 1.5. t = 0 and t = 1 give 1.5 x the first and last points; every colour lies within 1.5 x
// the points' range; mid-segment it is the Bezier midpoint (p0 + 3 p1 + 3 p2 + p3) / 8.
TEST(MarbleTexture, SplineEndsAndRange) {
  const RGB first = marble_colour(0.f), last = marble_colour(1.f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(first[c], 1.5f * (c < 2 ? 0.58f : 0.6f), 1e-6f);
    EXPECT_NEAR(last[c], 1.5f * (c < 2 ? 0.58f : 0.6f), 1e-6f);
  }
  for (int i = 0; i <= 600; ++i) {
    const RGB v = marble_colour(float(i) / 600.f);
    EXPECT_GE(v.r, 1.5f * 0.2f - 1e-5f);
    EXPECT_LE(v.r, 1.5f * 0.6f + 1e-5f);
    EXPECT_GE(v.b, 1.5f * 0.33f - 1e-5f);
    EXPECT_LE(v.b, 1.5f * 0.6f + 1e-5f);
  }
  // Halfway through the segment from {.58 .58 .6} x3 over {.5} (segment 1 at s = 1/2: points
  // 1..4 = .58 .58 .5 .6 in red): (p1 + 3 p2 + 3 p3 + p4) / 8.
  EXPECT_NEAR(marble_colour(1.5f / 6.f).r, 1.5f * (0.58f + 3 * 0.58f + 3 * 0.5f + 0.6f) / 8.f, 1e-5f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
