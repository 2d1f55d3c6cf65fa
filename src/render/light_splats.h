// Light that a camera sample sends to other pixels than its own: bdpt's t = 1 strategies
// connect a light-path vertex to the camera's lens, and the result lands wherever the camera
// sees that vertex. Collected per tile while it renders, in sample order, and added to the film
// after the pass on one thread, in (sample index, tile) order, so that every pixel's splat sum
// receives its terms in an order that neither the thread count nor the pass sizes change.
//
// Each splat is spread over the pixels around its film position with the pixel filter's
// weights, as pbrt-v4's RGBFilm::AddSplat, into the film's splat sums (Film::add_splat), which
// the image divides by the pixel's weight sum: eyetrace's filter weights have mean 1, so that
// is pbrt-v4's 1 / spp (its splatScale) wherever the filter is positive; the filter's integral
// divides as in pbrt-v4's GetPixelRGB.
#pragma once
#include <vector>

#include "core/camera.h"
#include "core/sampled_spectrum.h"
#include "core/spectrum.h"

namespace eyetrace {

class Film;

struct LightSplat {
  Vec2 p_raster{0.f};  // on the full film, in pixels
  int index = 0;       // the sample index of the camera sample that made it
  SampledSpectrum L{0.f};
  SampledWavelengths lambda;
};

// One tile's splats of one pass, with the camera they are seen through.
class LightSplats {
 public:
  explicit LightSplats(const Camera& camera) : camera_(&camera) {}
  const Camera& camera() const { return *camera_; }
  // The sample index that the next splats belong to (set before each camera sample).
  void start_sample(int index) { index_ = index; }
  // Black or non-finite splats are dropped (the film would count the latter as discarded).
  void add(Vec2 p_raster, const SampledSpectrum& L, const SampledWavelengths& lambda) {
    if (is_black(L) || !is_finite(L)) return;
    list_.push_back(LightSplat{p_raster, index_, L, lambda});
  }
  const std::vector<LightSplat>& list() const { return list_; }
  void clear() { list_.clear(); }

 private:
  const Camera* camera_;
  int index_ = 0;
  std::vector<LightSplat> list_;
};

// Adds splats to a film as the render loop does. Made once per render.
class LightSplatter {
 public:
  explicit LightSplatter(const Film& film);
  // Adds `tiles`' splats of sample indices [first, end) to the film, index by index and, within
  // an index, tile by tile in the order given, then empties the lists.
  void flush(Film& film, std::vector<LightSplats>& tiles, int first, int end) const;
  void add(Film& film, const LightSplat& s) const;

 private:
  // pbrt-v4's factor: 1 / (the filter's integral), times the full film's pixels over the film's
  // pixel bounds (one light path per camera sample of the crop, importance over the full film).
  float scale_;
};

}  // namespace eyetrace
