// The Halton sampler: sample j of pixel p must be the j-th Halton point (in index order) whose
// first two radical inverses, scaled by 2^a x 3^b, fall in p, found here by brute force with a
// radical inverse written out in the test; later dimensions are that point's later radical
// inverses; pbrt-v4's parameters.
#include "samplers/halton_sampler.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

double reference_radical_inverse(uint64_t i, int base) {
  double inv = 1.0 / base, f = inv, r = 0.0;
  for (; i > 0; i /= base, f *= inv) r += double(i % base) * f;
  return r;
}

// The first n base-b digits of i, reversed into an integer: the cell of i's radical inverse on
// a grid of b^n cells, computed exactly.
int leading_cell(uint64_t i, int base, int n) {
  int cell = 0;
  for (int k = 0; k < n; ++k, i /= base) cell = cell * base + int(i % base);
  return cell;
}

ParameterList halton_params(int spp, const std::string& randomization) {
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

TEST(HaltonSampler, PixelSamplesAreTheHaltonPointsInsideThePixel) {
  for (IVec2 res : {IVec2(8, 8), IVec2(5, 3), IVec2(20, 10)}) {
    // Scales 2^a >= width and 3^b >= height, as in pbrt-v4.
    int sx = 1, sy = 1, ex = 0, ey = 0;
    for (; sx < res.x; ++ex) sx *= 2;
    for (; sy < res.y; ++ey) sy *= 3;
    const int spp = 4;
    std::map<std::pair<int, int>, std::vector<uint64_t>> points;
    for (uint64_t i = 0; i < uint64_t(sx) * sy * spp; ++i) {
      int px = leading_cell(i, 2, ex), py = leading_cell(i, 3, ey);
      points[{px, py}].push_back(i);
    }
    ParameterList params = halton_params(spp, "none");
    auto s = create_halton_sampler(SamplerContext{params, res, 0, 0});
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const auto& indices = points[{x, y}];
        ASSERT_EQ(int(indices.size()), spp);
        for (int j = 0; j < spp; ++j) {
          uint64_t i = indices[size_t(j)];
          s->start_pixel_sample(IVec2(x, y), j);
          Vec2 u = s->get_pixel_2d();
          EXPECT_NEAR(u.x, reference_radical_inverse(i, 2) * sx - x, 1e-5) << x << "," << y << " j " << j;
          EXPECT_NEAR(u.y, reference_radical_inverse(i, 3) * sy - y, 1e-5) << x << "," << y << " j " << j;
          EXPECT_NEAR(s->get_1d(), reference_radical_inverse(i, 5), 1e-6);  // dimension 2: base 5
          Vec2 v = s->get_2d();                                             // dimensions 3, 4: bases 7, 11
          EXPECT_NEAR(v.x, reference_radical_inverse(i, 7), 1e-6);
          EXPECT_NEAR(v.y, reference_radical_inverse(i, 11), 1e-6);
        }
      }
  }
}

TEST(HaltonSampler, ImagesRepeatEvery128Pixels) {
  // pbrt-v4's documented behaviour: the pixel offset is computed from p mod 128.
  ParameterList params = halton_params(16, "permutedigits");
  auto s = create_halton_sampler(SamplerContext{params, IVec2(300, 300), 0, 0});
  s->start_pixel_sample(IVec2(5, 9), 3, 2);
  float a = s->get_1d();
  s->start_pixel_sample(IVec2(133, 137), 3, 2);
  EXPECT_EQ(s->get_1d(), a);
}

TEST(HaltonSampler, FactoryReadsPbrtParameters) {
  ParameterList defaults;
  auto s = create_halton_sampler(SamplerContext{defaults, IVec2(8, 8), 0, 0});
  EXPECT_EQ(s->samples_per_pixel(), 16);
  EXPECT_NE(s->to_string().find("randomization=permutedigits"), std::string::npos) << s->to_string();
  ParameterList fast = halton_params(16, "fastowen");  // pbrt-v4 rejects it for Halton too
  EXPECT_THROW(create_halton_sampler(SamplerContext{fast, IVec2(8, 8), 0, 0}), SceneError);
  ParameterList zero = halton_params(0, "");
  EXPECT_THROW(create_halton_sampler(SamplerContext{zero, IVec2(8, 8), 0, 0}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
