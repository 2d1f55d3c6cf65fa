// Sampler interface: deterministic in (pixel, sample index, dimension), so an image does not
// depend on how tiles are spread over threads. Each thread works on its own clone().
#pragma once
#include <cstdint>
#include <memory>

#include "core/math.h"

namespace eyetrace {

class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual int samples_per_pixel() const = 0;
  // Positions the sample stream at `sample_index` of `pixel`, starting at `dimension`.
  virtual void start_pixel_sample(IVec2 pixel, int sample_index, int dimension = 0) = 0;
  virtual float get_1d() = 0;
  virtual Vec2 get_2d() = 0;
  // The film-position sample; samplers may treat it specially (e.g. stratify it first).
  virtual Vec2 get_pixel_2d() = 0;
  virtual std::unique_ptr<Sampler> clone() const = 0;
  // Whether a pixel's first n samples are well spread for every n up to samples_per_pixel(), so
  // that adaptive sampling may stop a pixel anywhere (a stratified grid is not: its first
  // samples fill the first rows of strata).
  virtual bool progressive() const { return true; }
  virtual std::string to_string() const = 0;
};

}  // namespace eyetrace
