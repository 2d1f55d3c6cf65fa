// The Sobol' sequence over the whole image (pbrt-v4's SobolSampler): dimensions 0 and 1, scaled
// by the resolution rounded up to a power of two, choose the pixel, so a pixel's samples are the
// Sobol' points that fall in it, found directly by inverting the generator matrices over GF(2).
// Dimensions 2..1023 are the Joe-Kuo dimensions, randomised per dimension; beyond the table,
// dimensions are padded with independent hashed samples of (point, dimension, seed).
#pragma once
#include <memory>
#include <vector>

#include "core/sampler.h"
#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

// Finds the index of the frame-th Sobol' point inside pixel p of a 2^m x 2^m grid.
class SobolPixelIndexer {
 public:
  explicit SobolPixelIndexer(int log2_scale);
  uint64_t index(uint64_t frame, IVec2 pixel) const;
  int log2_scale() const { return m_; }

 private:
  // Pixel bits of the first 2 m index bits: (top m bits of dim 0) << m | (top m bits of dim 1).
  uint64_t pixel_bits(uint64_t index) const;
  int m_;
  std::vector<uint64_t> inverse_;      // column c: low index bits that produce pixel bit c
  std::vector<uint64_t> frame_delta_;  // column b: pixel bits produced by index bit 2 m + b
};

class SobolSampler : public Sampler {
 public:
  SobolSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed);
  int samples_per_pixel() const override { return spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override { return sample_dimension(dimension_++); }
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override;
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<SobolSampler>(*this); }
  std::string to_string() const override;

 private:
  float sample_dimension(int dim) const;

  int spp_;
  Randomization randomization_;
  uint64_t seed_;
  std::shared_ptr<const SobolPixelIndexer> indexer_;
  uint64_t sobol_index_ = 0;
  int dimension_ = 2;
};

// pbrt-v4 "sobol": integer pixelsamples (16), integer seed, string randomization ("fastowen";
// also "none", "permutedigits", "owen").
const PluginSpec& sobol_sampler_spec();
ParamSpec sobol_randomization_param();  // shared with zsobol
std::unique_ptr<Sampler> create_sobol_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
