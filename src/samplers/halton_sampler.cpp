#include "samplers/halton_sampler.h"

#include <fmt/format.h>

#include "samplers/sampler_params.h"

namespace eyetrace {

namespace {

int64_t positive_mod(int64_t a, int64_t n) {
  int64_t r = a % n;
  return r < 0 ? r + n : r;
}

// x with a x = 1 (mod n), by the extended Euclidean algorithm.
int64_t multiplicative_inverse(int64_t a, int64_t n) {
  int64_t old_r = a, r = n, old_s = 1, s = 0;
  while (r != 0) {
    int64_t q = old_r / r;
    int64_t t = old_r - q * r;
    old_r = r;
    r = t;
    t = old_s - q * s;
    old_s = s;
    s = t;
  }
  return positive_mod(old_s, n);
}

}  // namespace

HaltonSampler::HaltonSampler(int samples_per_pixel, IVec2 resolution, Randomization randomization, uint64_t seed)
    : spp_(samples_per_pixel), randomization_(randomization), seed_(seed) {
  if (randomization_ == Randomization::PermuteDigits) permutations_ = std::make_shared<const DigitPermutations>(seed);
  // Smallest 2^j and 3^k covering the (tile) resolution in x and y.
  for (int i = 0; i < 2; ++i) {
    int base = i == 0 ? 2 : 3, scale = 1, exp = 0;
    while (scale < std::min(resolution[i], kMaxResolution)) {
      scale *= base;
      ++exp;
    }
    base_scales_[i] = scale;
    base_exponents_[i] = exp;
  }
  mult_inverse_[0] = multiplicative_inverse(base_scales_[1], base_scales_[0]);
  mult_inverse_[1] = multiplicative_inverse(base_scales_[0], base_scales_[1]);
}

// The index of the pixel's first sample solves, by the Chinese remainder theorem, for the
// index whose first two radical inverses land in the pixel; later samples are a stride of
// 2^j 3^k apart, the period after which the pixel is visited again.
void HaltonSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  const uint64_t stride = uint64_t(base_scales_[0]) * uint64_t(base_scales_[1]);
  if (pixel != first_index_pixel_ && stride > 1) {
    first_index_ = 0;
    for (int i = 0; i < 2; ++i) {
      uint64_t pm = uint64_t(positive_mod(pixel[i], kMaxResolution));
      uint64_t offset = inverse_radical_inverse(pm, i == 0 ? 2 : 3, base_exponents_[i]);
      first_index_ += offset * (stride / uint64_t(base_scales_[i])) * uint64_t(mult_inverse_[i]);
    }
    first_index_ %= stride;
    first_index_pixel_ = pixel;
  }
  halton_index_ = first_index_ + uint64_t(sample_index) * stride;
  dimension_ = std::max(2, dimension);
}

float HaltonSampler::get_1d() {
  if (dimension_ >= kPrimeTableSize) dimension_ = 2;
  return sample_dimension(dimension_++);
}

Vec2 HaltonSampler::get_2d() {
  if (dimension_ + 1 >= kPrimeTableSize) dimension_ = 2;
  int dim = dimension_;
  dimension_ += 2;
  return Vec2(sample_dimension(dim), sample_dimension(dim + 1));
}

// The offset within the pixel: the digits of the first two radical inverses below the scale.
Vec2 HaltonSampler::get_pixel_2d() {
  return Vec2(radical_inverse(0, halton_index_ >> base_exponents_[0]),
              radical_inverse(1, halton_index_ / uint64_t(base_scales_[1])));
}

float HaltonSampler::sample_dimension(int dim) const {
  switch (randomization_) {
    case Randomization::None: return radical_inverse(dim, halton_index_);
    case Randomization::PermuteDigits: return permutations_->scrambled_radical_inverse(dim, halton_index_);
    default:
      return owen_scrambled_radical_inverse(dim, halton_index_, uint32_t(mix_bits((uint64_t(dim) << 32) ^ seed_)));
  }
}

std::string HaltonSampler::to_string() const {
  return fmt::format("HaltonSampler[pixelsamples={} seed={} randomization={} scales=({}, {})]", spp_, int64_t(seed_),
                     randomization_name(randomization_), base_scales_.x, base_scales_.y);
}

const PluginSpec& halton_sampler_spec() {
  static const PluginSpec spec{
      "Sampler", "the Halton sequence over the image plane", "—",
      pixel_sample_params(16) +
          std::vector<ParamSpec>{randomization_param(
              Randomization::PermuteDigits, {Randomization::None, Randomization::PermuteDigits, Randomization::Owen})}};
  return spec;
}

std::unique_ptr<Sampler> create_halton_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, halton_sampler_spec(), "halton");
  int spp = read_pixel_samples(ctx, p);
  uint64_t seed = read_seed(ctx, p);
  Randomization r = read_randomization(p);
  return std::make_unique<HaltonSampler>(spp, ctx.resolution, r, seed);
}

}  // namespace eyetrace
