// The film: accumulates weighted radiance per pixel in double precision, as linear sRGB: each
// sample's spectral radiance becomes CIE XYZ and then sRGB (core/spectrum.h) as it arrives. Each camera sample
// lands in one pixel (the filter is importance-sampled), so pixels are written by one thread.
// Non-finite samples are counted and discarded, never averaged into the image.
#pragma once
#include <atomic>
#include <memory>
#include <vector>

#include "core/filter.h"
#include "core/math.h"
#include "core/spectrum.h"
#include "render/image_io.h"

namespace eyetrace {

struct PixelBounds {
  IVec2 lo{0}, hi{0};  // [lo, hi)
  int width() const { return hi.x - lo.x; }
  int height() const { return hi.y - lo.y; }
  size_t area() const { return size_t(width()) * size_t(height()); }
};

// pbrt's cropwindow (x0, x1, y0, y1 as fractions) to pixel bounds, as pbrt-v4 rounds them.
PixelBounds crop_to_pixels(IVec2 resolution, Vec4 crop);

class Film {
 public:
  // `scale` multiplies every pixel (pbrt-v4's iso/exposure imaging ratio).
  Film(IVec2 resolution, PixelBounds bounds, std::unique_ptr<Filter> filter, float scale = 1.f);
  IVec2 resolution() const { return resolution_; }
  const PixelBounds& bounds() const { return bounds_; }
  const Filter& filter() const { return *filter_; }

  // Adds radiance L with filter weight w to `pixel` (absolute raster coordinates).
  // Returns false (and counts it) when L or w is not finite.
  bool add_sample(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float w) {
    return add_sample(pixel, sampled_to_rgb(L, lambda), w);
  }
  bool add_sample(IVec2 pixel, const RGB& L, float w) {
    if (!is_finite(L) || !std::isfinite(w)) {
      nonfinite_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    Pixel& px = pixels_[index(pixel)];
    px.sum[0] += double(w) * L.r;
    px.sum[1] += double(w) * L.g;
    px.sum[2] += double(w) * L.b;
    px.weight += w;
    return true;
  }
  RGB pixel_value(IVec2 pixel) const;
  Image image() const;  // the crop region, top row first
  uint64_t nonfinite_samples() const { return nonfinite_; }

  // The exact accumulators, 4 doubles per pixel (weighted r, g, b sums and the weight sum),
  // row-major over bounds(): a checkpoint stores them, and a film restored from them
  // continues bit for bit as if it had never stopped.
  std::vector<double> accumulators() const;
  // Throws std::invalid_argument unless `acc` holds 4 values per pixel.
  void restore(const std::vector<double>& acc, uint64_t nonfinite_samples);

 private:
  struct Pixel {
    double sum[3] = {0, 0, 0};
    double weight = 0;
  };
  size_t index(IVec2 p) const { return size_t(p.y - bounds_.lo.y) * bounds_.width() + (p.x - bounds_.lo.x); }
  IVec2 resolution_;
  PixelBounds bounds_;
  std::unique_ptr<Filter> filter_;
  float scale_;
  std::vector<Pixel> pixels_;
  std::atomic<uint64_t> nonfinite_{0};
};

}  // namespace eyetrace
