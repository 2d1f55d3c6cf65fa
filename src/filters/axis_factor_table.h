// A pixel filter's one-dimensional factor g(t) (core/filter.h: evaluate_axis) as a piecewise
// cubic, for the rows of factors a dispersive eye splats with (Filter::evaluate_axis_row): one
// table lookup and three multiply-adds per tap where the exact factor needs an exponential or
// a sine. g must be even in t and zero from the radius on (every filter here is).
#pragma once
#include <array>
#include <functional>
#include <vector>

namespace eyetrace {

class AxisFactorTable {
 public:
  AxisFactorTable() = default;
  // g on [0, radius] in `segments` equal segments, each the cubic through g at its ends and at
  // its thirds. The interpolation error is at most 5.1e-4 h^4 max|g''''| (h the segment width):
  // choose segments from the factor's own scale (a Gaussian's sigma, say).
  AxisFactorTable(const std::function<double(double)>& g, double radius, int segments);
  // out[i] = g(t0 - i) for i < n, never negative; 0 at and beyond the radius and for a NaN t0.
  void row(double t0, int n, float* out) const;
  double radius() const { return radius_; }

 private:
  std::vector<std::array<double, 4>> cubic_;  // per segment: coefficients of x^0..x^3, x = 3 u
  double radius_ = 0.0;
  double segments_per_unit_ = 0.0;
};

}  // namespace eyetrace
