#include "samplers/pmj02bn_sampler.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/constants.h"
#include "core/diagnostic.h"
#include "samplers/hash.h"
#include "samplers/pmj02bn_tables.h"
#include "samplers/sampler_params.h"

namespace eyetrace {

namespace {

bool is_power_of_4(uint32_t v) { return std::has_single_bit(v) && (std::countr_zero(v) % 2 == 0); }

uint32_t round_up_power_of_4(uint32_t v) {
  uint32_t p = 1;
  while (p < v) p *= 4;
  return p;
}

// Each pixel of a T x T tile gets the points of set 0 in its 1/T x 1/T part of the square,
// in the set's order, scaled to the pixel (in double precision, as pbrt-v4 sorts them: a
// float would put points on a border in the wrong pixel). A non-power-of-4 spp keeps the
// first spp of each pixel's points.
std::vector<Vec2> sort_into_pixels(int tile, int spp) {
  std::vector<Vec2> samples(size_t(tile) * tile * spp);
  std::vector<int> stored(size_t(tile) * tile, 0);
  for (uint32_t i = 0; i < kPmj02bnPoints; ++i) {
    const std::array<uint32_t, 2> q = pmj02bn_point(0, i);
    const double x = q[0] * 0x1p-32 * tile, y = q[1] * 0x1p-32 * tile;
    const size_t pixel = size_t(x) + size_t(y) * tile;
    if (stored[pixel] == spp) continue;
    samples[pixel * spp + stored[pixel]++] = Vec2(float(x - std::floor(x)), float(y - std::floor(y)));
  }
  return samples;
}

}  // namespace

Pmj02bnSampler::Pmj02bnSampler(int samples_per_pixel, uint64_t seed)
    : spp_(samples_per_pixel),
      seed_(seed),
      tile_(1 << (kPmj02bnLevels / 2 - std::countr_zero(round_up_power_of_4(uint32_t(samples_per_pixel))) / 2)),
      pixel_samples_(std::make_shared<const std::vector<Vec2>>(sort_into_pixels(tile_, samples_per_pixel))) {
  // The seed shifts every blue-noise texture by the same toroidal offset (pbrt-v4's do not
  // depend on the seed): another seed, other rotations, still blue noise across pixels.
  const uint64_t shift = hash_values(seed, 0x626c7565u);
  noise_shift_ = IVec2(int(shift % kBlueNoiseSize), int((shift >> 16) % kBlueNoiseSize));
}

void Pmj02bnSampler::start_pixel_sample(IVec2 pixel, int sample_index, int dimension) {
  pixel_ = pixel;
  index_ = sample_index;
  dimension_ = std::max(2, dimension);  // dimensions 0 and 1 are the film position's, as pbrt-v4
}

IVec2 Pmj02bnSampler::blue_noise_pixel() const {
  return IVec2(int((int64_t(pixel_.x) + noise_shift_.x) % kBlueNoiseSize),
               int((int64_t(pixel_.y) + noise_shift_.y) % kBlueNoiseSize));
}

float Pmj02bnSampler::get_1d() {
  const uint64_t h = hash_values(pixel_.x, pixel_.y, dimension_, seed_);
  const uint32_t stratum = permutation_element(uint32_t(index_), uint32_t(spp_), uint32_t(h));
  const float jitter = blue_noise(dimension_, blue_noise_pixel());
  ++dimension_;
  return std::min((float(stratum) + jitter) / float(spp_), kOneMinusEpsilon);
}

Vec2 Pmj02bnSampler::get_2d() {
  const int instance = dimension_ / 2;
  uint32_t index = uint32_t(index_);
  if (instance >= kPmj02bnSets)
    index = permutation_element(index, uint32_t(spp_), uint32_t(hash_values(pixel_.x, pixel_.y, dimension_, seed_)));
  const std::array<uint32_t, 2> q = pmj02bn_point(instance, index % kPmj02bnPoints);
  // Cranley-Patterson rotation, the same for all of a pixel's samples in this dimension pair
  // and blue noise across pixels.
  const IVec2 b = blue_noise_pixel();
  Vec2 u(float(q[0] * 0x1p-32) + blue_noise(dimension_, b), float(q[1] * 0x1p-32) + blue_noise(dimension_ + 1, b));
  dimension_ += 2;
  if (u.x >= 1.f) u.x -= 1.f;
  if (u.y >= 1.f) u.y -= 1.f;
  return Vec2(std::min(u.x, kOneMinusEpsilon), std::min(u.y, kOneMinusEpsilon));
}

Vec2 Pmj02bnSampler::get_pixel_2d() {
  // The seed shifts the tile (pbrt-v4's film positions do not depend on it, so two seeds'
  // images there share their film positions and their noise is correlated). Pixel
  // coordinates may be negative (a crop window's outside): wrap into the tile.
  const uint64_t shift = hash_values(seed_, 0x74696c65u);
  const int px = int((int64_t(pixel_.x) + int64_t(shift & 0xffff)) % tile_ + tile_) % tile_;
  const int py = int((int64_t(pixel_.y) + int64_t((shift >> 16) & 0xffff)) % tile_ + tile_) % tile_;
  return (*pixel_samples_)[(size_t(px) + size_t(py) * tile_) * spp_ + size_t(index_ % spp_)];
}

std::string Pmj02bnSampler::to_string() const {
  return fmt::format("Pmj02bnSampler[pixelsamples={} seed={} tile={}]", spp_, int64_t(seed_), tile_);
}

const PluginSpec& pmj02bn_sampler_spec() {
  static const PluginSpec spec{
      "Sampler", "progressive multi-jittered (0,2) points, tiled over pixels, as pbrt-v4's pmj02bn",
      "eyetrace makes its own tables at build time with the same constructions (5 sets of 65536 pmj02 points "
      "with best-candidate choice; 48 void-and-cluster textures of 128 x 128), not pbrt-v4's numbers; the seed also "
      "shifts the tile of film positions and the textures (pbrt-v4's seed changes only the permutations of 1-D strata "
      "and of the sets beyond the fifth dimension pair). At most 65536 samples per pixel, as pbrt-v4.",
      pixel_sample_params(16)};
  return spec;
}

std::unique_ptr<Sampler> create_pmj02bn_sampler(const SamplerContext& ctx) {
  const PluginParams p(ctx.params, pmj02bn_sampler_spec(), "pmj02bn");
  const int spp = read_pixel_samples(ctx, p);
  if (spp > int(kPmj02bnPoints))
    p.fail("pixelsamples",
           fmt::format("{} samples per pixel: pmj02bn has at most {} (as pbrt-v4)", spp, kPmj02bnPoints));
  // pbrt-v4 warns too: the pixel's part of the tile holds a power of 4 points.
  if (!is_power_of_4(uint32_t(spp)))
    warn(
        ctx.params.loc(),
        fmt::format(
            "pmj02bn sampler: {} samples per pixel is not a power of 4; results are best with 1, 4, 16, 64, ...", spp));
  return std::make_unique<Pmj02bnSampler>(spp, read_seed(ctx, p));
}

}  // namespace eyetrace
