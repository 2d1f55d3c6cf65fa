#include "samplers/padded_sobol_sampler.h"

#include <bit>

#include "core/diagnostic.h"
#include "samplers/hash.h"
#include "samplers/sampler_params.h"
#include "samplers/sobol_sampler.h"

namespace eyetrace {

float PaddedSobolSampler::get_1d() {
  const uint64_t h = hash_values(pixel_.x, pixel_.y, dimension_, seed_);
  ++dimension_;
  const uint32_t point = permutation_element(uint32_t(index_), uint32_t(spp_), uint32_t(h));
  return randomized_sobol_sample(point, 0, randomization_, uint32_t(h >> 32));
}

Vec2 PaddedSobolSampler::get_2d() {
  const uint64_t h = hash_values(pixel_.x, pixel_.y, dimension_, seed_);
  dimension_ += 2;
  const uint32_t point = permutation_element(uint32_t(index_), uint32_t(spp_), uint32_t(h));
  // One hash serves the permutation and both scramblings, as pbrt-v4's: its low word keys the
  // permutation and the first dimension's scrambling, its high word the second's.
  return Vec2(randomized_sobol_sample(point, 0, randomization_, uint32_t(h)),
              randomized_sobol_sample(point, 1, randomization_, uint32_t(h >> 32)));
}

std::string PaddedSobolSampler::to_string() const {
  return fmt::format("PaddedSobolSampler[pixelsamples={} seed={} randomization={}]", spp_, int64_t(seed_),
                     randomization_name(randomization_));
}

const PluginSpec& paddedsobol_sampler_spec() {
  static const PluginSpec spec{"Sampler",
                               "per-dimension Sobol' (0,2) points of each pixel, shuffled and scrambled per dimension",
                               "—", pixel_sample_params(16) + std::vector<ParamSpec>{sobol_randomization_param()}};
  return spec;
}

std::unique_ptr<Sampler> create_paddedsobol_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, paddedsobol_sampler_spec(), "paddedsobol");
  const int spp = read_pixel_samples(ctx, p);
  // pbrt-v4 warns too: a (0,2) set is only fully stratified at a power of two.
  if (!std::has_single_bit(uint32_t(spp)))
    warn(ctx.params.loc(),
         fmt::format("paddedsobol sampler: {} samples per pixel is not a power of two; its strata are uneven", spp));
  return std::make_unique<PaddedSobolSampler>(spp, read_randomization(p), read_seed(ctx, p));
}

}  // namespace eyetrace
