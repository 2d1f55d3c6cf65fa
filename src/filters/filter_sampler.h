// Importance sampling of pixel filters that have no analytic inverse (gaussian, mitchell), as
// pbrt-v4's FilterSampler: |f| tabulated on a grid over [-radius, radius]^2, sampled as a
// piecewise-constant 2D distribution, and each sample weighted by f(p) / (pdf(p) * integral f),
// so the weight is signed where f is negative (Mitchell's lobes) and has mean exactly 1.
// The distributions here serve filters only (the light-sampling ones live in core/distribution.h).
#pragma once
#include <vector>

#include "core/filter.h"
#include "core/math.h"

namespace eyetrace::filter_sampling {

// A piecewise-constant density on [lo, hi] proportional to non-negative cell values.
class Distribution1D {
 public:
  Distribution1D(std::vector<float> values, float lo, float hi);
  // x in [lo, hi], its density and cell; u in [0, 1).
  float sample(float u, float* pdf, int* cell) const;
  float integral() const { return integral_; }  // of the cell values over [lo, hi]
  int size() const { return int(values_.size()); }
  float value(int cell) const { return values_[size_t(cell)]; }

 private:
  std::vector<float> values_;
  std::vector<double> cdf_;  // size() + 1 entries from 0 to 1
  float lo_, hi_;
  float integral_ = 0.f;
};

// A piecewise-constant density on a rectangle: a marginal over rows, a conditional per row.
class Distribution2D {
 public:
  // values[y * nx + x], cell (x, y) of an nx x ny grid over [lo, hi].
  Distribution2D(const std::vector<float>& values, int nx, int ny, Vec2 lo, Vec2 hi);
  Vec2 sample(Vec2 u, float* pdf) const;
  float integral() const { return marginal_.integral(); }

 private:
  std::vector<Distribution1D> conditional_;
  Distribution1D marginal_;
};

class FilterSampler {
 public:
  // `cells` per axis; `integral` is the filter's exact (signed) integral, used to normalise weights.
  FilterSampler(const Filter& filter, IVec2 cells, float integral);
  FilterSample sample(const Filter& filter, Vec2 u) const;

 private:
  Distribution2D distribution_;
  float integral_;
};

// Cells per axis for a filter of this radius: 32 per pixel of radius as pbrt-v4, within limits.
int filter_table_cells(float radius, int min_cells = 8);

}  // namespace eyetrace::filter_sampling
