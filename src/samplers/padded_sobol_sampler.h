// pbrt-v4's "paddedsobol" sampler: each 1-D or 2-D sample is the first one or two Sobol'
// dimensions of a pixel's own point set of samples-per-pixel points, the point chosen by a
// pseudo-random permutation of the sample index and randomised (pbrt-v4's "randomization"),
// both keyed by a hash of (pixel, dimension, seed). Successive dimensions are thus independent
// (0,2)-sequence padding, each well stratified over all of a pixel's samples; a prefix of the
// samples is a random subset, so adaptive sampling does not accept it (progressive() false).
#pragma once
#include <memory>

#include "core/sampler.h"
#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

class PaddedSobolSampler : public Sampler {
 public:
  PaddedSobolSampler(int samples_per_pixel, Randomization randomization, uint64_t seed)
      : spp_(samples_per_pixel), randomization_(randomization), seed_(seed) {}
  int samples_per_pixel() const override { return spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override {
    pixel_ = pixel;
    index_ = sample_index;
    dimension_ = dimension;
  }
  float get_1d() override;
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override { return get_2d(); }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<PaddedSobolSampler>(*this); }
  bool progressive() const override { return false; }
  std::string to_string() const override;

 private:
  int spp_;
  Randomization randomization_;
  uint64_t seed_;
  IVec2 pixel_{0};
  int index_ = 0, dimension_ = 0;
};

// pbrt-v4 "paddedsobol": integer pixelsamples (16), integer seed, string randomization
// ("fastowen"; also "none", "permutedigits", "owen").
const PluginSpec& paddedsobol_sampler_spec();
std::unique_ptr<Sampler> create_paddedsobol_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
