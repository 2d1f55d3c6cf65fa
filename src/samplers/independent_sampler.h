// Independent uniform random samples: the reference every other sampler must agree with in
// expectation. The PCG32 stream of a pixel is chosen by a hash of (pixel, seed) and jumped to
// (sample index, dimension), so no state is shared between pixels.
#pragma once
#include <memory>

#include "core/sampler.h"
#include "samplers/rng.h"
#include "scene/registry.h"

namespace eyetrace {

class IndependentSampler : public Sampler {
 public:
  IndependentSampler(int samples_per_pixel, uint64_t seed) : spp_(samples_per_pixel), seed_(seed) {}
  int samples_per_pixel() const override { return spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override { return rng_.next_float(); }
  Vec2 get_2d() override {
    float x = rng_.next_float();
    return Vec2(x, rng_.next_float());
  }
  Vec2 get_pixel_2d() override { return get_2d(); }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }
  std::string to_string() const override;

 private:
  int spp_;
  uint64_t seed_;
  Pcg32 rng_;
};

// pbrt-v4 "independent": integer pixelsamples (4), integer seed.
const PluginSpec& independent_sampler_spec();
std::unique_ptr<Sampler> create_independent_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
