// The independent sampler's factory: pbrt-v4's defaults, the --spp override, the seed sources.
// (Uniformity, determinism and clones are in sampler_properties_test.cpp.)
#include "samplers/independent_sampler.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

ParameterList int_params(std::vector<std::pair<const char*, double>> values) {
  ParameterList params;
  for (auto [name, v] : values) {
    Param p;
    p.type = "integer";
    p.name = name;
    p.numbers = {v};
    params.add(p);
  }
  return params;
}

float first_value(Sampler& s) {
  s.start_pixel_sample(IVec2(1, 1), 0);
  return s.get_1d();
}

TEST(IndependentSampler, DefaultsToFourSamplesAsPbrtV4) {
  ParameterList params;
  EXPECT_EQ(create_independent_sampler(SamplerContext{params, IVec2(4, 4), 0, 0})->samples_per_pixel(), 4);
}

TEST(IndependentSampler, SppOverrideReplacesPixelSamples) {
  ParameterList params = int_params({{"pixelsamples", 32}});
  EXPECT_EQ(create_independent_sampler(SamplerContext{params, IVec2(4, 4), 0, 0})->samples_per_pixel(), 32);
  EXPECT_EQ(create_independent_sampler(SamplerContext{params, IVec2(4, 4), 3, 0})->samples_per_pixel(), 3);
}

TEST(IndependentSampler, SeedParameterOverridesTheCommandLineSeed) {
  ParameterList none;
  ParameterList seeded = int_params({{"seed", 5}});
  auto from_cli = create_independent_sampler(SamplerContext{none, IVec2(4, 4), 0, 5});
  auto from_scene = create_independent_sampler(SamplerContext{seeded, IVec2(4, 4), 0, 99});
  auto other = create_independent_sampler(SamplerContext{none, IVec2(4, 4), 0, 6});
  EXPECT_EQ(first_value(*from_cli), first_value(*from_scene));
  EXPECT_NE(first_value(*from_cli), first_value(*other));
  EXPECT_NE(from_scene->to_string().find("seed=5"), std::string::npos) << from_scene->to_string();
}

TEST(IndependentSampler, RejectsSampleCountsOutOfRange) {
  for (double n : {0.0, -1.0, double((1 << 24) + 1)}) {
    ParameterList params = int_params({{"pixelsamples", n}});
    EXPECT_THROW(create_independent_sampler(SamplerContext{params, IVec2(4, 4), 0, 0}), SceneError) << n;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
