// Parameters every sampler reads the same way (pbrt-v4 names): "pixelsamples" (replaced by the
// command line's --spp), "seed" (default: --seed) and "randomization", declared once here and
// added to each sampler's table.
#pragma once
#include <string>
#include <vector>

#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

inline constexpr int kMaxPixelSamples = 1 << 24;

// "pixelsamples" with the sampler's default, and "seed".
std::vector<ParamSpec> pixel_sample_params(int default_spp);
// "seed" alone (stratified counts its samples by xsamples and ysamples).
ParamSpec seed_param();
// "randomization" among `choices`, default `def`.
ParamSpec randomization_param(Randomization def, std::vector<Randomization> choices);

// "pixelsamples" (or the --spp override).
int read_pixel_samples(const SamplerContext& ctx, const PluginParams& params);
// The command line's --spp value, checked; 0 when it was not given.
int spp_override(const SamplerContext& ctx);
// "seed" if given in the scene, else the command line's seed.
uint64_t read_seed(const SamplerContext& ctx, const PluginParams& params);
Randomization read_randomization(const PluginParams& params);

}  // namespace eyetrace
