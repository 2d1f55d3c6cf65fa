#include "samplers/stratified_sampler.h"

#include <fmt/format.h>

#include <cmath>

#include "samplers/sampler_params.h"

namespace eyetrace {

namespace {

// (stratum + offset) / n rounded to a float that still lies in [stratum / n, (stratum + 1) / n):
// with the offset close to 1, plain float arithmetic can round into the next stratum.
float point_in_stratum(uint32_t stratum, float offset, int n) {
  float f = float((double(stratum) + double(offset)) / double(n));
  while (double(f) * n >= double(stratum) + 1.0) f = std::nextafter(f, 0.f);
  while (double(f) * n < double(stratum)) f = std::nextafter(f, 1.f);
  return f;
}

}  // namespace

void StratifiedSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  pixel_ = pixel;
  sample_index_ = sample_index;
  dimension_ = dimension;
  rng_.set_sequence(hash_values(pixel.x, pixel.y, seed_));
  rng_.advance(uint64_t(sample_index) * 65536ull + uint64_t(dimension));
}

// Sample i of the pixel takes stratum perm(i) in this dimension: a bijection over the pixel's
// samples, so every stratum is used exactly once.
uint32_t StratifiedSampler::stratum() const {
  uint32_t h = uint32_t(hash_values(pixel_.x, pixel_.y, dimension_, seed_));
  return permutation_element(uint32_t(sample_index_), uint32_t(samples_per_pixel()), h);
}

float StratifiedSampler::get_1d() {
  uint32_t s = stratum();
  ++dimension_;
  return point_in_stratum(s, offset(), samples_per_pixel());
}

Vec2 StratifiedSampler::get_2d() {
  uint32_t s = stratum();
  dimension_ += 2;
  uint32_t x = s % uint32_t(x_samples_), y = s / uint32_t(x_samples_);
  float dx = offset();
  float dy = offset();
  return Vec2(point_in_stratum(x, dx, x_samples_), point_in_stratum(y, dy, y_samples_));
}

std::string StratifiedSampler::to_string() const {
  return fmt::format("StratifiedSampler[xsamples={} ysamples={} jitter={} seed={}]", x_samples_, y_samples_, jitter_,
                     int64_t(seed_));
}

const PluginSpec& stratified_sampler_spec() {
  static const PluginSpec spec{
      "Sampler",
      "one jittered sample per cell of an xsamples × ysamples grid",
      "—",
      {param::integer("xsamples", 4).range(1, kMaxPixelSamples).describe("strata across"),
       param::integer("ysamples", 4).range(1, kMaxPixelSamples).describe("strata down"),
       param::boolean("jitter", true).describe("random position within each stratum"), seed_param()}};
  return spec;
}

std::unique_ptr<Sampler> create_stratified_sampler(const SamplerContext& ctx) {
  const PluginParams params(ctx.params, stratified_sampler_spec(), "stratified");
  bool jitter = params.get_bool("jitter");
  int xs = params.get_int("xsamples");
  int ys = params.get_int("ysamples");
  if (int64_t(xs) * ys > kMaxPixelSamples)
    params.fail("xsamples",
                fmt::format("xsamples x ysamples = {} is more than {}", int64_t(xs) * ys, kMaxPixelSamples));
  if (int n = spp_override(ctx); n > 0) {
    int div = int(std::sqrt(double(n)));
    while (n % div != 0) --div;
    xs = n / div;
    ys = div;
  }
  return std::make_unique<StratifiedSampler>(xs, ys, jitter, read_seed(ctx, params));
}

}  // namespace eyetrace
