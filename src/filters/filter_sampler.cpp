#include "filters/filter_sampler.h"

#include <algorithm>
#include <cmath>

namespace eyetrace::filter_sampling {

Distribution1D::Distribution1D(std::vector<float> values, float lo, float hi)
    : values_(std::move(values)), cdf_(values_.size() + 1, 0.0), lo_(lo), hi_(hi) {
  size_t n = values_.size();
  double dx = double(hi - lo) / double(n), sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    sum += double(values_[i]) * dx;
    cdf_[i + 1] = sum;
  }
  integral_ = float(sum);
  // An all-zero table has no shape to follow: sample it uniformly rather than divide by zero.
  for (size_t i = 1; i <= n; ++i) cdf_[i] = sum > 0.0 ? cdf_[i] / sum : double(i) / double(n);
}

float Distribution1D::sample(float u, float* pdf, int* cell) const {
  int n = size();
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u));
  int o = std::clamp(int(it - cdf_.begin()) - 1, 0, n - 1);
  double width = cdf_[o + 1] - cdf_[o];
  double du = width > 0.0 ? (double(u) - cdf_[o]) / width : 0.5;
  *cell = o;
  *pdf = integral_ > 0.f ? values_[size_t(o)] / integral_ : 1.f / (hi_ - lo_);
  double x = double(lo_) + (double(o) + std::clamp(du, 0.0, 1.0)) / double(n) * double(hi_ - lo_);
  return std::clamp(float(x), lo_, hi_);
}

Distribution2D::Distribution2D(const std::vector<float>& values, int nx, int ny, Vec2 lo, Vec2 hi)
    : marginal_({0.f}, lo.y, hi.y) {
  std::vector<float> row_integrals;
  for (int y = 0; y < ny; ++y) {
    std::vector<float> row(values.begin() + ptrdiff_t(y) * nx, values.begin() + ptrdiff_t(y + 1) * nx);
    conditional_.emplace_back(std::move(row), lo.x, hi.x);
    row_integrals.push_back(conditional_.back().integral());
  }
  marginal_ = Distribution1D(std::move(row_integrals), lo.y, hi.y);
}

Vec2 Distribution2D::sample(Vec2 u, float* pdf) const {
  float pdf_x, pdf_y;
  int row, column;
  float y = marginal_.sample(u.y, &pdf_y, &row);
  float x = conditional_[size_t(row)].sample(u.x, &pdf_x, &column);
  *pdf = pdf_x * pdf_y;
  return Vec2(x, y);
}

// Each cell holds the mean of |f| at four interior points, a better estimate of the cell's
// mass than its centre alone, and not zero where f crosses zero at the centre.
static std::vector<float> tabulate_abs(const Filter& filter, IVec2 cells) {
  Vec2 r = filter.radius();
  std::vector<float> values(size_t(cells.x) * size_t(cells.y));
  for (int y = 0; y < cells.y; ++y)
    for (int x = 0; x < cells.x; ++x) {
      float sum = 0.f;
      for (float fy : {0.25f, 0.75f})
        for (float fx : {0.25f, 0.75f}) {
          Vec2 p(-r.x + 2.f * r.x * (float(x) + fx) / float(cells.x),
                 -r.y + 2.f * r.y * (float(y) + fy) / float(cells.y));
          sum += std::abs(filter.evaluate(p));
        }
      values[size_t(y) * size_t(cells.x) + size_t(x)] = 0.25f * sum;
    }
  return values;
}

FilterSampler::FilterSampler(const Filter& filter, IVec2 cells, float integral)
    : distribution_(tabulate_abs(filter, cells), cells.x, cells.y, -filter.radius(), filter.radius()),
      integral_(integral) {}

FilterSample FilterSampler::sample(const Filter& filter, Vec2 u) const {
  float pdf;
  Vec2 p = distribution_.sample(u, &pdf);
  if (!(pdf > 0.f) || !(integral_ > 0.f)) return FilterSample{p, 0.f};
  return FilterSample{p, filter.evaluate(p) / (pdf * integral_)};
}

int filter_table_cells(float radius, int min_cells) {
  return std::clamp(int(std::ceil(32.f * radius)), min_cells, 1024);
}

}  // namespace eyetrace::filter_sampling
