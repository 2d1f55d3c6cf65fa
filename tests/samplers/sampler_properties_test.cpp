// Properties every sampler must have, checked for each sampler and randomisation: values in
// [0, 1), uniform in every 1D dimension and 2D pair (chi-square), reproducible from (pixel,
// sample index, dimension) whatever was asked before, and clones that continue the same stream.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "../support/chi2.h"
#include "../support/unity_id.h"
#include "samplers/halton_sampler.h"
#include "samplers/independent_sampler.h"
#include "samplers/padded_sobol_sampler.h"
#include "samplers/pmj02bn_sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zsobol_sampler.h"
#include "scene/params.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

struct Case {
  std::string name;
  std::function<std::unique_ptr<Sampler>(const SamplerContext&)> factory;
  std::string randomization;  // "" for samplers without the parameter
  bool jitter = true;
};

const IVec2 kResolution(8, 8);
constexpr int kSpp = 256;

std::unique_ptr<Sampler> make(const Case& c, uint64_t seed = 7) {
  ParameterList params;
  auto add = [&](const char* type, const char* name, std::vector<double> numbers, std::vector<std::string> strings,
                 std::vector<bool> bools) {
    Param p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(numbers);
    p.strings = std::move(strings);
    p.bools = std::move(bools);
    params.add(std::move(p));
  };
  if (c.name.rfind("stratified", 0) == 0) {
    add("integer", "xsamples", {16}, {}, {});
    add("integer", "ysamples", {16}, {}, {});
    add("bool", "jitter", {}, {}, {c.jitter});
  } else {
    add("integer", "pixelsamples", {kSpp}, {}, {});
  }
  if (!c.randomization.empty()) add("string", "randomization", {}, {c.randomization}, {});
  SamplerContext ctx{params, kResolution, 0, seed};
  return c.factory(ctx);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases = {{"independent", create_independent_sampler, ""},
                             {"stratified_jittered", create_stratified_sampler, "", true},
                             {"stratified_centred", create_stratified_sampler, "", false},
                             {"pmj02bn", create_pmj02bn_sampler, ""}};
  for (const char* r : {"none", "permutedigits", "owen"})
    cases.push_back({std::string("halton_") + r, create_halton_sampler, r});
  for (const char* r : {"none", "permutedigits", "fastowen", "owen"}) {
    cases.push_back({std::string("sobol_") + r, create_sobol_sampler, r});
    cases.push_back({std::string("zsobol_") + r, create_zsobol_sampler, r});
    cases.push_back({std::string("paddedsobol_") + r, create_paddedsobol_sampler, r});
  }
  return cases;
}

// Chi-square results for every dimension and pair a camera path would draw, pooled over all
// pixels of an 8 x 8 image with 256 samples each (16384 points per histogram); far dimensions
// lie past the Halton prime table (256) and the Sobol' matrices (1024).
std::vector<chi2::Result> uniformity_results(Sampler& sampler) {
  const int n_1d = 6, n_2d = 3;
  std::vector<chi2::Grid2D> hist_1d(n_1d + 2, chi2::Grid2D(64, 1, 0.0, 1.0, 0.0, 1.0));
  std::vector<chi2::Grid2D> hist_2d(n_2d + 3, chi2::Grid2D(16, 16, 0.0, 1.0, 0.0, 1.0));
  auto in_unit = [](float u) { return u >= 0.f && u < 1.f; };
  int out_of_range = 0;
  for (int y = 0; y < kResolution.y; ++y)
    for (int x = 0; x < kResolution.x; ++x)
      for (int i = 0; i < kSpp; ++i) {
        sampler.start_pixel_sample(IVec2(x, y), i);
        Vec2 p = sampler.get_pixel_2d();
        out_of_range += !in_unit(p.x) || !in_unit(p.y);
        hist_2d[0].add(p.x, p.y);
        for (int d = 0; d < n_1d; ++d) {
          float u = sampler.get_1d();
          out_of_range += !in_unit(u);
          hist_1d[size_t(d)].add(u, 0.5);
        }
        for (int d = 0; d < n_2d; ++d) {
          Vec2 u = sampler.get_2d();
          out_of_range += !in_unit(u.x) || !in_unit(u.y);
          hist_2d[size_t(d) + 1].add(u.x, u.y);
        }
        int k = 0;
        for (int start : {300, 1100}) {
          sampler.start_pixel_sample(IVec2(x, y), i, start);
          float u = sampler.get_1d();
          Vec2 v = sampler.get_2d();
          out_of_range += !in_unit(u) || !in_unit(v.x) || !in_unit(v.y);
          hist_1d[size_t(n_1d + k)].add(u, 0.5);
          hist_2d[size_t(n_2d + 1 + k)].add(v.x, v.y);
          ++k;
        }
      }
  EXPECT_EQ(out_of_range, 0) << "values outside [0, 1)";
  const double n = double(kResolution.x) * kResolution.y * kSpp;
  std::vector<chi2::Result> results;
  for (const auto* group : {&hist_1d, &hist_2d})
    for (const chi2::Grid2D& g : *group) {
      std::vector<double> expected(g.counts.size(), n / double(g.counts.size()));
      results.push_back(chi2::pearson(g.counts, expected));
    }
  return results;
}

class SamplerProperties : public ::testing::TestWithParam<Case> {};

TEST_P(SamplerProperties, EveryDimensionIsUniform) {
  auto sampler = make(GetParam());
  ASSERT_EQ(sampler->samples_per_pixel(), kSpp);
  std::vector<chi2::Result> results = uniformity_results(*sampler);
  // Family-wise significance 1e-4 over the histograms of one sampler (Bonferroni).
  const double significance = 1e-4 / double(results.size());
  for (size_t h = 0; h < results.size(); ++h)
    EXPECT_TRUE(results[h].passes(significance)) << h << ": " << results[h].summary();
}

// A sampler whose later dimensions are slightly biased (u -> u^1.05): the same check must catch it.
class BiasedSampler : public IndependentSampler {
 public:
  BiasedSampler() : IndependentSampler(kSpp, 1) {}
  float get_1d() override { return std::pow(IndependentSampler::get_1d(), 1.05f); }
};

TEST(SamplerUniformityCheck, RejectsASlightlyBiasedSampler) {
  BiasedSampler biased;
  std::vector<chi2::Result> results = uniformity_results(biased);
  double min_p = 1.0;
  for (const chi2::Result& r : results) min_p = std::min(min_p, r.p_value);
  EXPECT_LT(min_p, 1e-4 / double(results.size()));
}

TEST_P(SamplerProperties, ValuesDependOnlyOnPixelIndexAndDimension) {
  auto a = make(GetParam());
  auto b = make(GetParam());
  auto draw = [](Sampler& s, IVec2 p, int i, int d) {
    s.start_pixel_sample(p, i, d);
    float u = s.get_1d();
    Vec2 v = s.get_2d();
    return std::vector<float>{u, v.x, v.y};
  };
  // b has drawn from other pixels, indices and dimensions in between; a has not.
  for (IVec2 p : {IVec2(0, 0), IVec2(5, 3), IVec2(7, 7)})
    for (int i : {0, 1, 200}) {
      draw(*b, IVec2(2, 6), 17, 5);
      draw(*b, p, i + 1, 0);
      EXPECT_EQ(draw(*a, p, i, 4), draw(*b, p, i, 4));
    }
}

TEST_P(SamplerProperties, StartingAtADimensionSkipsTheDimensionsBefore) {
  // From dimension 2 on (0 and 1 are the film position for the global samplers), starting at
  // dimension d equals starting at 2 and drawing d - 2 values.
  auto s = make(GetParam());
  for (int d : {2, 3, 7, 20}) {
    s->start_pixel_sample(IVec2(3, 4), 9, d);
    float direct = s->get_1d();
    s->start_pixel_sample(IVec2(3, 4), 9, 2);
    for (int k = 2; k < d; ++k) s->get_1d();
    EXPECT_EQ(s->get_1d(), direct) << "dimension " << d;
  }
}

TEST_P(SamplerProperties, RestartAfterTheCameraDimensionsContinuesTheStream) {
  // The integrator draws a sample's six camera dimensions (film 2-D, lens 2-D, time,
  // wavelength), generates camera rays in batches, then restarts the sample at dimension 6
  // for the path: the path must see the values an uninterrupted stream would give.
  auto camera_dims = [](Sampler& s, IVec2 p, int i) {
    s.start_pixel_sample(p, i);
    s.get_pixel_2d();
    s.get_2d();
    s.get_1d();
    s.get_1d();
  };
  auto path_dims = [](Sampler& s) {
    std::vector<float> v;
    for (int k = 0; k < 6; ++k) {
      v.push_back(s.get_1d());
      Vec2 u = s.get_2d();
      v.insert(v.end(), {u.x, u.y});
    }
    return v;
  };
  auto a = make(GetParam());
  auto b = make(GetParam());
  for (IVec2 p : {IVec2(0, 0), IVec2(5, 3)})
    for (int i : {0, 1, 7}) {
      camera_dims(*a, p, i);
      camera_dims(*b, p, i);
      camera_dims(*b, IVec2(2, 6), 3);  // another sample's camera dimensions in between
      b->start_pixel_sample(p, i, 6);
      EXPECT_EQ(path_dims(*a), path_dims(*b)) << "pixel " << p.x << "," << p.y << " sample " << i;
    }
}

TEST_P(SamplerProperties, CloneContinuesTheSameStream) {
  auto s = make(GetParam());
  s->start_pixel_sample(IVec2(1, 2), 3);
  s->get_pixel_2d();
  s->get_1d();
  auto c = s->clone();
  EXPECT_EQ(c->samples_per_pixel(), s->samples_per_pixel());
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(c->get_1d(), s->get_1d());
    EXPECT_EQ(c->get_2d(), s->get_2d());
  }
}

TEST_P(SamplerProperties, SeedChangesTheValues) {
  if (GetParam().randomization == "none" || GetParam().name == "stratified_centred") GTEST_SKIP() << "not random";
  auto a = make(GetParam(), 1), b = make(GetParam(), 2);
  int differ = 0;
  for (int i = 0; i < 16; ++i) {
    a->start_pixel_sample(IVec2(2, 2), i, 2);
    b->start_pixel_sample(IVec2(2, 2), i, 2);
    differ += a->get_1d() != b->get_1d();
  }
  EXPECT_GE(differ, 12);
}

TEST_P(SamplerProperties, ToStringNamesItsParameters) {
  auto s = make(GetParam());
  std::string text = s->to_string();
  EXPECT_NE(text.find("Sampler["), std::string::npos) << text;
  EXPECT_NE(text.find("seed=7"), std::string::npos) << text;
  if (!GetParam().randomization.empty()) {
    EXPECT_NE(text.find("randomization=" + GetParam().randomization), std::string::npos) << text;
  }
}

INSTANTIATE_TEST_SUITE_P(AllSamplers, SamplerProperties, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& param_info) { return param_info.param.name; });

}  // namespace EYETRACE_UNITY_ID
}  // namespace
