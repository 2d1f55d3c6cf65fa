// Pixel reconstruction filter. Filters are importance-sampled (pbrt-v4's approach): each
// camera sample lands in exactly one pixel with weight f/pdf, so tiles never share pixels
// and images do not depend on thread scheduling.
#pragma once
#include <string>

#include "core/math.h"

namespace eyetrace {

struct FilterSample {
  Vec2 offset{0.f};  // from the pixel centre, in pixels, within [-radius, radius]
  float weight = 1.f;
};

class Filter {
 public:
  virtual ~Filter() = default;
  virtual Vec2 radius() const = 0;
  virtual float evaluate(Vec2 p) const = 0;
  virtual FilterSample sample(Vec2 u) const = 0;
  // True when the filter has one value over its whole support (a box): every sample then has
  // weight 1, and radiance may be splatted to another pixel without changing the pixel's weight.
  virtual bool constant() const { return false; }
  virtual std::string to_string() const = 0;
};

}  // namespace eyetrace
