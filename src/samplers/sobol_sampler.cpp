#include "samplers/sobol_sampler.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "samplers/sampler_params.h"

namespace eyetrace {

// Dimensions 0 and 1 form a (0,2)-sequence: the 2^(2m) points of each aligned block of indices
// hit every pixel of the 2^m x 2^m grid once, so the linear map from the low 2m index bits to
// the 2m pixel bits is invertible. Gauss-Jordan elimination on (pixel bits, index bits) pairs
// turns the pixel side into unit vectors; the index side then holds the inverse's columns.
SobolPixelIndexer::SobolPixelIndexer(int log2_scale) : m_(log2_scale) {
  if (m_ == 0) return;
  int n = 2 * m_;
  std::vector<uint64_t> pix(n), idx(n);
  for (int c = 0; c < n; ++c) {
    pix[c] = pixel_bits(uint64_t(1) << c);
    idx[c] = uint64_t(1) << c;
  }
  for (int r = 0; r < n; ++r) {
    int pivot = r;
    while (pivot < n && !((pix[pivot] >> r) & 1)) ++pivot;
    if (pivot == n) throw std::logic_error("Sobol' pixel map is singular");
    std::swap(pix[r], pix[pivot]);
    std::swap(idx[r], idx[pivot]);
    for (int k = 0; k < n; ++k)
      if (k != r && ((pix[k] >> r) & 1)) {
        pix[k] ^= pix[r];
        idx[k] ^= idx[r];
      }
  }
  inverse_ = idx;
  for (int b = n; b < kSobolMatrixSize; ++b) frame_delta_.push_back(pixel_bits(uint64_t(1) << b));
}

uint64_t SobolPixelIndexer::pixel_bits(uint64_t index) const {
  uint64_t x = sobol_bits(index, 0) >> (32 - m_), y = sobol_bits(index, 1) >> (32 - m_);
  return (x << m_) | y;
}

uint64_t SobolPixelIndexer::index(uint64_t frame, IVec2 pixel) const {
  if (m_ == 0) return frame;
  uint64_t mask = (uint64_t(1) << m_) - 1;
  uint64_t target = ((uint64_t(uint32_t(pixel.x)) & mask) << m_) | (uint64_t(uint32_t(pixel.y)) & mask);
  // The frame's own index bits already move the point; the low bits must make up the rest.
  for (size_t b = 0; b < frame_delta_.size() && (frame >> b) != 0; ++b)
    if ((frame >> b) & 1) target ^= frame_delta_[b];
  uint64_t low = 0;
  for (int r = 0; r < 2 * m_; ++r)
    if ((target >> r) & 1) low ^= inverse_[r];
  return (frame << (2 * m_)) | low;
}

SobolSampler::SobolSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed)
    : spp_(samples_per_pixel), randomization_(randomization), seed_(seed) {
  uint32_t scale = std::bit_ceil(uint32_t(std::max({resolution.x, resolution.y, 1})));
  indexer_ = std::make_shared<const SobolPixelIndexer>(std::countr_zero(scale));
}

void SobolSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  sobol_index_ = indexer_->index(uint64_t(sample_index), pixel);
  dimension_ = std::max(2, dimension);
}

Vec2 SobolSampler::get_2d() {
  Vec2 u(sample_dimension(dimension_), sample_dimension(dimension_ + 1));
  dimension_ += 2;
  return u;
}

// The digits below the pixel's own: shifting them up keeps all 32 bits of precision.
Vec2 SobolSampler::get_pixel_2d() {
  int m = indexer_->log2_scale();
  return Vec2(bits_to_unit_float(sobol_bits(sobol_index_, 0) << m),
              bits_to_unit_float(sobol_bits(sobol_index_, 1) << m));
}

float SobolSampler::sample_dimension(int dim) const {
  if (dim >= kSobolDimensions) return hash_to_unit_float(hash_values(sobol_index_, dim, seed_));
  uint32_t h = uint32_t(mix_bits((uint64_t(dim) << 32) ^ seed_));
  return randomized_sobol_sample(sobol_index_, dim, randomization_, h);
}

std::string SobolSampler::to_string() const {
  return fmt::format("SobolSampler[pixelsamples={} seed={} randomization={} scale={}]", spp_, int64_t(seed_),
                     randomization_name(randomization_), 1 << indexer_->log2_scale());
}

const PluginSpec& sobol_sampler_spec() {
  static const PluginSpec spec{"Sampler",
                               "the Sobol' sequence over the image plane (a count that is not a power of two warns)",
                               "Images wider or taller than 65536 pixels are an error (use `zsobol`).",
                               pixel_sample_params(16) + std::vector<ParamSpec>{sobol_randomization_param()}};
  return spec;
}

ParamSpec sobol_randomization_param() {
  return randomization_param(Randomization::FastOwen, {Randomization::None, Randomization::PermuteDigits,
                                                       Randomization::FastOwen, Randomization::Owen});
}

std::unique_ptr<Sampler> create_sobol_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, sobol_sampler_spec(), "sobol");
  int spp = read_pixel_samples(ctx, p);
  uint64_t seed = read_seed(ctx, p);
  Randomization r = read_randomization(p);
  if (std::max(ctx.resolution.x, ctx.resolution.y) > 65536)
    fail(ctx.params.loc(), "the sobol sampler supports resolutions up to 65536 pixels; use \"zsobol\"");
  if (!std::has_single_bit(uint32_t(spp)))
    warn(ctx.params.loc(), fmt::format("sobol sampler: {} samples per pixel is not a power of two, which "
                                       "stratifies less well",
                                       spp));
  return std::make_unique<SobolSampler>(spp, ctx.resolution, r, seed);
}

}  // namespace eyetrace
