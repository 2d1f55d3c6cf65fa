// Parameters every sampler reads the same way (pbrt-v4 names): "pixelsamples" (replaced by the
// command line's --spp), "seed" (default: --seed) and "randomization".
#pragma once
#include <string>

#include "samplers/lowdiscrepancy.h"
#include "scene/registry.h"

namespace eyetrace {

inline constexpr int kMaxPixelSamples = 1 << 24;

// "pixelsamples" (or the --spp override), checked to lie in [1, 2^24].
int read_pixel_samples(const SamplerContext& ctx, int default_spp);
// The command line's --spp value, checked; 0 when it was not given.
int spp_override(const SamplerContext& ctx);
// "seed" if given in the scene, else the command line's seed.
uint64_t read_seed(const SamplerContext& ctx);
// "randomization": one of none, permutedigits, fastowen, owen (fastowen only where allowed).
Randomization read_randomization(const ParameterList& params, Randomization def, bool allow_fastowen);

}  // namespace eyetrace
