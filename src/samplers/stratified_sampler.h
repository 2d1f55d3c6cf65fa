// Jittered stratified sampling: each dimension (and each 2D pair) of a pixel's samples falls in
// its own stratum of an xsamples x ysamples grid, the strata shuffled per (pixel, dimension) by a
// hashed permutation so dimensions are not correlated (pbrt-v4's StratifiedSampler).
#pragma once
#include <memory>

#include "core/sampler.h"
#include "samplers/rng.h"
#include "scene/registry.h"

namespace eyetrace {

class StratifiedSampler : public Sampler {
 public:
  StratifiedSampler(int x_samples, int y_samples, bool jitter, uint64_t seed)
      : x_samples_(x_samples), y_samples_(y_samples), jitter_(jitter), seed_(seed) {}
  int samples_per_pixel() const override { return x_samples_ * y_samples_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override;
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override { return get_2d(); }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }
  bool progressive() const override { return false; }
  std::string to_string() const override;

 private:
  uint32_t stratum() const;
  float offset() { return jitter_ ? rng_.next_float() : 0.5f; }

  int x_samples_, y_samples_;
  bool jitter_;
  uint64_t seed_;
  Pcg32 rng_;
  IVec2 pixel_{0};
  int sample_index_ = 0, dimension_ = 0;
};

// pbrt-v4 "stratified": integer xsamples (4), ysamples (4), bool jitter (true), integer seed.
// --spp N replaces xsamples x ysamples by the most nearly square factorisation of N.
const PluginSpec& stratified_sampler_spec();
std::unique_ptr<Sampler> create_stratified_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
