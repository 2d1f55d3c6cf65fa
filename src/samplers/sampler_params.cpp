#include "samplers/sampler_params.h"

#include <fmt/format.h>

namespace eyetrace {

int spp_override(const SamplerContext& ctx) {
  if (ctx.spp_override <= 0) return 0;
  if (ctx.spp_override > kMaxPixelSamples)
    throw_error(fmt::format("--spp {} is more than the {} samples per pixel a sampler supports", ctx.spp_override,
                            kMaxPixelSamples));
  return ctx.spp_override;
}

int read_pixel_samples(const SamplerContext& ctx, int default_spp) {
  int spp = ctx.params.get_int("pixelsamples", default_spp);
  if (spp < 1 || spp > kMaxPixelSamples)
    ctx.params.fail("pixelsamples", fmt::format("value {} is outside [1, {}]", spp, kMaxPixelSamples));
  int over = spp_override(ctx);
  return over > 0 ? over : spp;
}

uint64_t read_seed(const SamplerContext& ctx) {
  int seed = ctx.params.get_int("seed", 0);
  return ctx.params.has("seed") ? uint64_t(int64_t(seed)) : ctx.seed;
}

Randomization read_randomization(const ParameterList& params, Randomization def, bool allow_fastowen) {
  std::string s = params.get_string("randomization", randomization_name(def));
  if (s == "none") return Randomization::None;
  if (s == "permutedigits") return Randomization::PermuteDigits;
  if (s == "owen") return Randomization::Owen;
  if (s == "fastowen") {
    if (!allow_fastowen) params.fail("randomization", "\"fastowen\" is not supported by this sampler (use \"owen\")");
    return Randomization::FastOwen;
  }
  params.fail("randomization",
              fmt::format("unknown value \"{}\"; expected \"none\", \"permutedigits\", \"fastowen\" or \"owen\"", s));
}

}  // namespace eyetrace
