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
  // The filter's signed integral over its support (what normalises sample weights and splats).
  virtual float integral() const = 0;
  // Every filter is a product of one-dimensional factors, f(x, y) = evaluate_axis(x, 0) *
  // evaluate_axis(y, 1) (tests/filters/separable_filters_test.cpp): a dispersive eye splats
  // with them (core/wavelength_splat.h). The default divides out f(0, 0); filters override it
  // where the factor is cheaper on its own.
  virtual float evaluate_axis(float t, int axis) const {
    return axis == 0 ? evaluate(Vec2(t, 0.f)) / evaluate(Vec2(0.f)) : evaluate(Vec2(0.f, t));
  }
  // The factors of a row of pixels one apart: out[i] = evaluate_axis(t0 - i, axis), i < n (a
  // wavelength's splat, one row per axis). Filters override it where the row is cheaper whole.
  virtual void evaluate_axis_row(double t0, int n, int axis, float* out) const {
    for (int i = 0; i < n; ++i) out[i] = evaluate_axis(float(t0 - i), axis);
  }
  // True when the filter has one value over its whole support (a box): every sample then has
  // weight 1, and radiance may be splatted to another pixel without changing the pixel's weight.
  virtual bool constant() const { return false; }
  virtual std::string to_string() const = 0;
};

}  // namespace eyetrace
