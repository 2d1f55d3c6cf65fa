#include "filters/axis_factor_table.h"

#include <algorithm>
#include <cmath>

namespace eyetrace {

AxisFactorTable::AxisFactorTable(const std::function<double(double)>& g, double radius, int segments)
    : radius_(radius), segments_per_unit_(segments / radius) {
  cubic_.resize(size_t(segments));
  const double h = radius / segments;
  for (int i = 0; i < segments; ++i) {
    // Newton's forward differences on the nodes x = 0, 1, 2, 3 (u = x / 3 across the segment),
    // then the power basis in x: p(x) = y0 + d1 x + d2 x (x - 1) / 2 + d3 x (x - 1) (x - 2) / 6.
    double y[4];
    for (int k = 0; k < 4; ++k) y[k] = g((i + k / 3.0) * h);
    const double d1 = y[1] - y[0], d2 = y[2] - 2.0 * y[1] + y[0], d3 = y[3] - 3.0 * y[2] + 3.0 * y[1] - y[0];
    cubic_[size_t(i)] = {y[0], d1 - d2 / 2.0 + d3 / 3.0, d2 / 2.0 - d3 / 2.0, d3 / 6.0};
  }
}

// Branch-free, so that the taps' multiply-add chains overlap: a tap beyond the support (or NaN)
// is evaluated at 0 and then zeroed.
void AxisFactorTable::row(double t0, int n, float* out) const {
  const int last = static_cast<int>(cubic_.size()) - 1;
  for (int i = 0; i < n; ++i) {
    const double a = std::abs(t0 - i);
    const bool inside = a < radius_;
    const double s = (inside ? a : 0.0) * segments_per_unit_;
    const int k = std::min(static_cast<int>(s), last);  // s is in [0, segments]
    const std::array<double, 4>& c = cubic_[static_cast<size_t>(k)];
    const double x = 3.0 * (s - static_cast<double>(k));
    const double value = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
    out[i] = inside ? static_cast<float>(std::max(0.0, value)) : 0.f;
  }
}

}  // namespace eyetrace
