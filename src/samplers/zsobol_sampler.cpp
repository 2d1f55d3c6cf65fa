#include "samplers/zsobol_sampler.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "samplers/sampler_params.h"
#include "samplers/sobol_sampler.h"

namespace eyetrace {

namespace {

// All 24 permutations of four base-4 digit values.
constexpr uint8_t kPermutations[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 2, 1}, {0, 3, 1, 2}, {1, 0, 2, 3}, {1, 0, 3, 2},
    {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 2, 0}, {1, 3, 0, 2}, {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 0, 1, 3}, {2, 0, 3, 1},
    {2, 3, 0, 1}, {2, 3, 1, 0}, {3, 1, 2, 0}, {3, 1, 0, 2}, {3, 2, 1, 0}, {3, 2, 0, 1}, {3, 0, 2, 1}, {3, 0, 1, 2}};

}  // namespace

ZSobolSampler::ZSobolSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed,
                             LensDimensions lens)
    : randomization_(randomization), seed_(seed), lens_(lens) {
  log2_spp_ = std::countr_zero(std::bit_ceil(uint32_t(std::max(samples_per_pixel, 1))));
  int res = int(std::bit_ceil(uint32_t(std::max({resolution.x, resolution.y, 1}))));
  n_base4_digits_ = std::countr_zero(uint32_t(res)) + (log2_spp_ + 1) / 2;
  // The pixel digits (above first_sample_digit, sample_index()) start at this bit.
  const bool odd = log2_spp_ & 1;
  const int first_pixel_digit = (log2_spp_ + (odd ? 1 : 0)) / 2;
  pixel_shift_ = 2 * first_pixel_digit - (odd ? 1 : 0);
  tile_cache_ = 2 * (n_base4_digits_ - first_pixel_digit) <= 32;
}

void ZSobolSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  dimension_ = dimension;
  morton_index_ = (encode_morton2(uint32_t(pixel.x), uint32_t(pixel.y)) << log2_spp_) | uint64_t(sample_index);
  if (pixel != cached_pixel_) {
    cached_pixel_ = pixel;
    if (++stamp_ == 0) {  // wrapped: forget every stamp so none can match by accident
      stamps_.fill(0);
      stamp_ = 1;
    }
    slot_ = (pixel.x & 15) | ((pixel.y & 15) << 4);
    TileSlot& slot = tile_[size_t(slot_)];
    if (slot.pixel != pixel) {  // another pixel's: its digits are stale (read only where valid)
      slot.pixel = pixel;
      slot.valid = 0;
    }
  }
}

// Each base-4 digit of the Morton index is permuted by a permutation chosen from a hash of
// the digits above it and of the dimension: a bijection on indices (so sample counts per
// pixel are kept) that randomises the order in which sub-quadrants are visited. With an odd
// log2(spp), the last digit is a single bit, flipped or not by the same kind of hash.
uint64_t ZSobolSampler::permuted_digits(int from, int to, uint64_t dim_salt) const {
  const bool odd = log2_spp_ & 1;
  uint64_t index = 0;
  for (int i = from; i >= to; --i) {
    int shift = 2 * i - (odd ? 1 : 0);
    int digit = int((morton_index_ >> shift) & 3);
    uint64_t higher = morton_index_ >> (shift + 2);
    int p = int((mix_bits(higher ^ dim_salt) >> 24) % 24);
    index |= uint64_t(kPermutations[p][digit]) << shift;
  }
  return index;
}

// The digits above the sample bits depend on the pixel and the dimension only, and cost most of
// the hashing (about 9 of 11 digits at 512 pixels, 16 spp): they are computed once per pixel and
// dimension and kept until the pixel changes. The result is the same bits either way.
uint64_t ZSobolSampler::sample_index() const { return sample_index(dimension_); }

uint64_t ZSobolSampler::sample_index(int dimension) const {
  const bool odd = log2_spp_ & 1;
  const int last_digit = odd ? 1 : 0;
  const int first_sample_digit = (log2_spp_ + (odd ? 1 : 0)) / 2 - 1;  // highest digit below the pixel bits
  const uint64_t dim_salt = 0x55555555ull * uint64_t(uint32_t(dimension));
  uint64_t pixel_part;
  if (dimension >= 0 && dimension < kCachedDimensions) {
    if (stamps_[size_t(dimension)] != stamp_) {
      uint64_t digits;
      TileSlot& slot = tile_[size_t(slot_)];
      const bool tiled = tile_cache_ && dimension < kTileDimensions;
      if (tiled && (slot.valid >> dimension & 1u)) {
        digits = uint64_t(slot.digits[size_t(dimension)]) << pixel_shift_;
      } else {
        digits = permuted_digits(n_base4_digits_ - 1, first_sample_digit + 1, dim_salt);
        if (tiled) {
          slot.digits[size_t(dimension)] = uint32_t(digits >> pixel_shift_);
          slot.valid |= 1u << dimension;
        }
      }
      pixel_digits_[size_t(dimension)] = digits;
      stamps_[size_t(dimension)] = stamp_;
    }
    pixel_part = pixel_digits_[size_t(dimension)];
  } else {
    pixel_part = permuted_digits(n_base4_digits_ - 1, first_sample_digit + 1, dim_salt);
  }
  uint64_t index = pixel_part | permuted_digits(first_sample_digit, last_digit, dim_salt);
  if (odd) {
    uint64_t bit = morton_index_ & 1;
    index |= bit ^ (mix_bits((morton_index_ >> 1) ^ dim_salt) & 1);
  }
  return index;
}

float ZSobolSampler::get_1d() {
  uint64_t index = sample_index();
  ++dimension_;
  uint32_t h = uint32_t(mix_bits(uint64_t(uint32_t(dimension_)) ^ seed_));
  return randomized_sobol_sample(index, 0, randomization_, h);
}

// With joint lens dimensions, the lens sample (dimensions 2-3, drawn right after the film
// position) takes Sobol' dimensions 2 and 3 of the film sample's own index instead of
// dimensions 0 and 1 of a differently shuffled one: a pixel's samples are then a 4-D net over
// film position and pupil together, which is what a defocused pixel integrates.
Vec2 ZSobolSampler::get_2d() {
  const bool joint = lens_ == LensDimensions::Joint && dimension_ == kLensDimension;
  uint64_t index = sample_index(joint ? 0 : dimension_);
  dimension_ += 2;
  uint64_t bits = mix_bits(uint64_t(uint32_t(dimension_)) ^ seed_);
  const int first = joint ? 2 : 0;
  return Vec2(randomized_sobol_sample(index, first, randomization_, uint32_t(bits)),
              randomized_sobol_sample(index, first + 1, randomization_, uint32_t(bits >> 32)));
}

std::string ZSobolSampler::to_string() const {
  return fmt::format("ZSobolSampler[pixelsamples={} seed={} randomization={} lensdimensions={}]", samples_per_pixel(),
                     int64_t(seed_), randomization_name(randomization_),
                     lens_ == LensDimensions::Joint ? "joint" : "padded");
}

const PluginSpec& zsobol_sampler_spec() {
  static const PluginSpec spec{
      "Sampler", "Sobol' points in Morton (Z) order of the pixels; a count that is not a power of two is rounded up",
      "eyetrace addition `lensdimensions`: `joint` (default) draws the lens/pupil sample from Sobol' dimensions 2–3 "
      "of the film sample's own index, so a pixel's samples form a 4-D net over film position and pupil; `padded` "
      "is pbrt-v4's behaviour (every 2-D sample from its own shuffled index). See docs/performance.md.",
      pixel_sample_params(16) +
          std::vector<ParamSpec>{sobol_randomization_param(),
                                 param::string("lensdimensions", "joint")
                                     .in({"joint", "padded"})
                                     .describe("how the lens sample is drawn (see differences)")}};
  return spec;
}

std::unique_ptr<Sampler> create_zsobol_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, zsobol_sampler_spec(), "zsobol");
  int spp = read_pixel_samples(ctx, p);
  uint64_t seed = read_seed(ctx, p);
  Randomization r = read_randomization(p);
  const std::string lens = p.get_string("lensdimensions");
  if (!std::has_single_bit(uint32_t(spp)))
    warn(ctx.params.loc(), fmt::format("zsobol sampler: {} samples per pixel rounded up to the power of two {}", spp,
                                       std::bit_ceil(uint32_t(spp))));
  return std::make_unique<ZSobolSampler>(
      spp, ctx.resolution, r, seed,
      lens == "joint" ? ZSobolSampler::LensDimensions::Joint : ZSobolSampler::LensDimensions::Padded);
}

}  // namespace eyetrace
