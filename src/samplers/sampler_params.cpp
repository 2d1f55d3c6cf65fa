#include "samplers/sampler_params.h"

#include <fmt/format.h>

namespace eyetrace {

ParamSpec seed_param() {
  return param::integer("seed")
      .shown_default("--seed, else 0")
      .describe("seeds the sample values (pbrt-v4 Option \"seed\" too)");
}

std::vector<ParamSpec> pixel_sample_params(int default_spp) {
  return {param::integer("pixelsamples", default_spp)
              .range(1, kMaxPixelSamples)
              .describe("samples per pixel (--spp replaces it)"),
          seed_param()};
}

ParamSpec randomization_param(Randomization def, std::vector<Randomization> choices) {
  std::vector<std::string> names;
  for (Randomization r : choices) names.push_back(randomization_name(r));
  return param::string("randomization", randomization_name(def)).in(names).describe("scrambling of the points");
}

int spp_override(const SamplerContext& ctx) {
  if (ctx.spp_override <= 0) return 0;
  if (ctx.spp_override > kMaxPixelSamples)
    throw_error(fmt::format("--spp {} is more than the {} samples per pixel a sampler supports", ctx.spp_override,
                            kMaxPixelSamples));
  return ctx.spp_override;
}

int read_pixel_samples(const SamplerContext& ctx, const PluginParams& params) {
  const int over = spp_override(ctx);
  return over > 0 ? over : params.get_int("pixelsamples");
}

uint64_t read_seed(const SamplerContext& ctx, const PluginParams& params) {
  return params.has("seed") ? uint64_t(int64_t(params.get_int("seed"))) : ctx.seed;
}

Randomization read_randomization(const PluginParams& params) {
  const std::string s = params.get_string("randomization");  // one of the declared choices
  if (s == "permutedigits") return Randomization::PermuteDigits;
  if (s == "owen") return Randomization::Owen;
  if (s == "fastowen") return Randomization::FastOwen;
  return Randomization::None;
}

}  // namespace eyetrace
