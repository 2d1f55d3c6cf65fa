// The Halton sequence over the whole image (pbrt-v4's HaltonSampler): its first two dimensions,
// scaled by 2^j x 3^k >= the resolution, visit every pixel in turn, so a pixel's samples are the
// points of one global low-discrepancy sequence. Images wider or taller than 128 pixels reuse
// the pattern of a 128 x 128 tile (as pbrt-v4): pixels 128 apart see the same points.
// Dimensions past the prime table (256 primes) wrap around to dimension 2.
#pragma once
#include <limits>
#include <memory>

#include "core/sampler.h"
#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

class HaltonSampler : public Sampler {
 public:
  HaltonSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed);
  int samples_per_pixel() const override { return spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override;
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override;
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<HaltonSampler>(*this); }
  std::string to_string() const override;

  static constexpr int kMaxResolution = 128;

 private:
  float sample_dimension(int dim) const;

  int spp_;
  Randomization randomization_;
  uint64_t seed_;
  std::shared_ptr<const DigitPermutations> permutations_;  // shared by clones (read only)
  IVec2 base_scales_{1}, base_exponents_{0};
  int64_t mult_inverse_[2] = {0, 0};
  uint64_t halton_index_ = 0;
  int dimension_ = 0;
  // The index of the last pixel's first sample: a pixel's samples come one after another, and
  // the digit reversals that find it cost a tenth of a path-traced render's sampling.
  IVec2 first_index_pixel_{std::numeric_limits<int>::min()};
  uint64_t first_index_ = 0;
};

// pbrt-v4 "halton": integer pixelsamples (16), integer seed, string randomization
// ("permutedigits"; also "none", "owen").
const PluginSpec& halton_sampler_spec();
std::unique_ptr<Sampler> create_halton_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
