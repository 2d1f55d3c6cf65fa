// pbrt-v4's "pmj02bn" sampler: progressive multi-jittered (0,2) points with best-candidate
// selection (samplers/pmj02bn_points.h). As pbrt-v4's:
// - the film position: the pixels of a T x T tile share the first set's points, each pixel
//   taking those that fall in its own 1/T x 1/T part of the square (T^2 x spp = 65536, spp
//   rounded up to a power of 4), so a pixel's positions are a (0,m,2)-net and neighbouring
//   pixels' samples are stratified across pixel borders (the seed shifts the tile: pbrt-v4's
//   film positions do not depend on the seed);
// - 2-D samples: dimension pair k uses set k (the first five pairs: the same point of the
//   set for a given sample index in every pixel; beyond them a permuted index) with a
//   per-pixel Cranley-Patterson rotation;
// - 1-D samples: a permuted stratum of the pixel's spp, jittered by a per-pixel offset;
// - the rotations and offsets of dimension d are texture d of 48 blue-noise textures of
//   128 x 128 pixels (samplers/blue_noise.h, embedded by samplers/pmj02bn_tables.h), tiled
//   over the image (shifted by the seed).
// A pixel's samples are a permuted subset in the 1-D dimensions, so adaptive sampling does
// not accept it (progressive() false).
#pragma once
#include <memory>
#include <vector>

#include "core/sampler.h"
#include "scene/registry.h"

namespace eyetrace {

class Pmj02bnSampler : public Sampler {
 public:
  Pmj02bnSampler(int samples_per_pixel, uint64_t seed);
  int samples_per_pixel() const override { return spp_; }
  void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) override;
  float get_1d() override;
  Vec2 get_2d() override;
  Vec2 get_pixel_2d() override;
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<Pmj02bnSampler>(*this); }
  bool progressive() const override { return false; }
  std::string to_string() const override;

  int pixel_tile_size() const { return tile_; }

 private:
  IVec2 blue_noise_pixel() const;  // where the pixel reads the blue-noise textures
  int spp_;
  uint64_t seed_;
  int tile_;              // T: pixels per side of the tile that shares the first set's points
  IVec2 noise_shift_{0};  // the seed's offset into the blue-noise textures
  std::shared_ptr<const std::vector<Vec2>> pixel_samples_;  // T^2 x spp, pixel by pixel
  IVec2 pixel_{0};
  int index_ = 0, dimension_ = 0;
};

// pbrt-v4 "pmj02bn": integer pixelsamples (16), integer seed.
const PluginSpec& pmj02bn_sampler_spec();
std::unique_ptr<Sampler> create_pmj02bn_sampler(const SamplerContext& ctx);

}  // namespace eyetrace
