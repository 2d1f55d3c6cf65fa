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

const PluginSpec& independent_sampler_spec() {
  static const PluginSpec spec{"Sampler", "independent uniform random samples", "—", pixel_sample_params(4)};
  return spec;
}

std::unique_ptr<Sampler> create_independent_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, independent_sampler_spec(), "independent");
  return std::make_unique<IndependentSampler>(read_pixel_samples(ctx, p), read_seed(ctx, p));
}

}  // namespace eyetrace
