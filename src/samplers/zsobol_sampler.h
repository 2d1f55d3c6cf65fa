// pbrt-v4's default sampler (Ahmed & Wonka 2020, "Screen-space blue-noise diffusion of Monte
// Carlo sampling error via hierarchical ordering of pixels"): pixels are ordered along a Morton
// (Z) curve and each pixel's samples take consecutive Sobol' indices, with the base-4 digits of
// the index shuffled by hashed permutations so that neighbouring pixels get well-spread, not
// repeated, points. Only the first two Sobol' dimensions are used, re-scrambled per dimension;
// since a pixel's 2^k samples are an aligned block of indices, each 1D and 2D projection of them
// is a (0,k,2)-net: every sample has its own elementary interval.
#pragma once
#include <array>
#include <memory>

#include "core/sampler.h"
#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

class ZSobolSampler : public Sampler {
 public:
  // Padded: every 2-D sample is Sobol' dimensions 0-1 of its own shuffled index (pbrt-v4).
  // Joint: the lens sample shares the film sample's index (see get_2d()).
  enum class LensDimensions { Joint, Padded };
  // The film position and lens sample are dimensions 0-1 and 2-3 (integrator.cpp draws them so).
  static constexpr int kLensDimension = 2;
  // samples_per_pixel must be a power of two (the factory rounds up).
  ZSobolSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed,
                LensDimensions lens = LensDimensions::Joint);
  int samples_per_pixel() const override { return 1 << log2_spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override;
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override { return get_2d(); }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<ZSobolSampler>(*this); }
  std::string to_string() const override;

  // The Sobol' index of the current (pixel, sample) for the current (or a given) dimension.
  uint64_t sample_index() const;
  uint64_t sample_index(int dimension) const;

 private:
  // Permuted digits from..to (inclusive, base-4 digit positions, from >= to) of the index.
  uint64_t permuted_digits(int from, int to, uint64_t dim_salt) const;

  static constexpr int kCachedDimensions = 64;
  Randomization randomization_;
  uint64_t seed_;
  LensDimensions lens_;
  int log2_spp_ = 0, n_base4_digits_ = 0;
  uint64_t morton_index_ = 0;
  int dimension_ = 0;
  // Per-pixel cache of the permuted pixel digits, by dimension (see sample_index()).
  IVec2 cached_pixel_{-1};
  uint32_t stamp_ = 1;
  mutable std::array<uint32_t, kCachedDimensions> stamps_{};
  mutable std::array<uint64_t, kCachedDimensions> pixel_digits_{};
  // Behind it, for the order a splatting render takes (sample index outermost over a 16 x 16
  // tile, so the pixel changes at every sample): the pixel digits of the first kTileDimensions
  // dimensions of the last pixel seen at each position of a tile, shifted down by pixel_shift_
  // (they fit 32 bits up to 65536 pixels across; tile_cache_ is false beyond).
  static constexpr int kTileSlots = 256, kTileDimensions = 16;
  struct TileSlot {
    IVec2 pixel{-1};
    uint32_t valid = 0;  // bit d: digits[d] is set
    std::array<uint32_t, kTileDimensions> digits{};
  };
  mutable std::array<TileSlot, kTileSlots> tile_{};
  int slot_ = 0;
  int pixel_shift_ = 0;
  bool tile_cache_ = false;
};

// pbrt-v4 "zsobol": integer pixelsamples (16; rounded up to a power of two), integer seed,
// string randomization ("fastowen"; also "none", "permutedigits", "owen"), and eyetrace's
// string lensdimensions ("joint"; "padded" is pbrt-v4's behaviour).
const PluginSpec& zsobol_sampler_spec();
std::unique_ptr<Sampler> create_zsobol_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
