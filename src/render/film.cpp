#include "render/film.h"

#include <stdexcept>

namespace eyetrace {

PixelBounds crop_to_pixels(IVec2 res, Vec4 crop) {
  PixelBounds b;
  b.lo = IVec2(int(std::ceil(res.x * crop[0])), int(std::ceil(res.y * crop[2])));
  b.hi = IVec2(int(std::ceil(res.x * crop[1])), int(std::ceil(res.y * crop[3])));
  b.lo = glm::clamp(b.lo, IVec2(0), res);
  b.hi = glm::clamp(b.hi, b.lo, res);
  return b;
}

Film::Film(IVec2 resolution, PixelBounds bounds, std::unique_ptr<Filter> filter, float scale)
    : resolution_(resolution), bounds_(bounds), filter_(std::move(filter)), scale_(scale), pixels_(bounds.area()) {}

RGB Film::pixel_value(IVec2 p) const {
  const Pixel& px = pixels_[index(p)];
  if (px.weight == 0) return RGB(0.f);
  double k = scale_ / px.weight;
  return RGB(float(px.sum[0] * k), float(px.sum[1] * k), float(px.sum[2] * k));
}

Image Film::image() const {
  Image img;
  img.width = bounds_.width();
  img.height = bounds_.height();
  img.channels = 3;
  img.pixels.resize(size_t(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      RGB v = pixel_value(bounds_.lo + IVec2(x, y));
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = std::isfinite(v[c]) ? v[c] : 0.f;
    }
  return img;
}

std::vector<double> Film::accumulators() const {
  std::vector<double> acc;
  acc.reserve(pixels_.size() * 4);
  for (const Pixel& p : pixels_) acc.insert(acc.end(), {p.sum[0], p.sum[1], p.sum[2], p.weight});
  return acc;
}

void Film::restore(const std::vector<double>& acc, uint64_t nonfinite_samples) {
  if (acc.size() != pixels_.size() * 4) throw std::invalid_argument("Film::restore: wrong number of accumulators");
  for (size_t i = 0; i < pixels_.size(); ++i) {
    const double* a = &acc[4 * i];
    pixels_[i] = Pixel{{a[0], a[1], a[2]}, a[3]};
  }
  nonfinite_ = nonfinite_samples;
}

}  // namespace eyetrace
