#include "samplers/independent_sampler.h"

#include <fmt/format.h>

#include "samplers/sampler_params.h"

namespace eyetrace {

// Each dimension consumes one value and a pixel sample never reaches 2^16 of them, so
// sample i starts 2^16 * i values into the pixel's stream.
void IndependentSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  rng_.set_sequence(hash_values(pixel.x, pixel.y, seed_));
  rng_.advance(uint64_t(sample_index) * 65536ull + uint64_t(dimension));
}

std::string IndependentSampler::to_string() const {
  return fmt::format("IndependentSampler[pixelsamples={} seed={}]", spp_, int64_t(seed_));
}

std::unique_ptr<Sampler> create_independent_sampler(const SamplerContext& ctx) {
  int spp = read_pixel_samples(ctx, 4);
  return std::make_unique<IndependentSampler>(spp, read_seed(ctx));
}

}  // namespace eyetrace
