#include "materials/piecewise_linear_2d.h"

#include <utility>

#include "core/constants.h"

namespace eyetrace {

namespace {

// Solves for t in [0, 1] the integral of the linear a(1-t) + b t from 0 to t = x, when a != b;
// `a + b` small against their difference falls back to the constant piece.
float invert_linear(float x, float a, float b) {
  const bool is_const = std::abs(a - b) < 1e-4f * (a + b);
  return is_const ? 2.f * x / (a + b) : (a - safe_sqrt(a * a - 2.f * x * (a - b))) / (a - b);
}

// The cell a scaled coordinate falls in, kept inside the table: pbrt-v4 truncates (so
// (-1, 0] is cell 0 and the upper edge belongs to the last cell); far outside or NaN, which
// pbrt-v4 would index out of bounds with, clamps here (the value then extrapolates or is NaN,
// which the caller rejects).
int cell(float v, int n) { return v >= 0.f ? std::min(int(std::min(v, float(n))), n - 2) : 0; }

}  // namespace

PiecewiseLinear2D::PiecewiseLinear2D(const float* data, int nx, int ny, std::vector<std::vector<float>> params,
                                     bool warp)
    : nx_(nx), ny_(ny), params_(std::move(params)), strides_(params_.size(), 0) {
  uint32_t slices = 1;
  for (int i = int(params_.size()) - 1; i >= 0; --i) {
    strides_[i] = params_[i].size() > 1 ? slices : 0;
    slices *= uint32_t(params_[i].size());
  }
  const size_t n = size_t(slices) * nx_ * ny_;
  if (!warp) {
    data_.assign(data, data + n);
    return;
  }
  build_cdfs(data, slices);
}

// Per slice: the conditional CDF along each row (trapezoids, in double), the marginal CDF of
// the rows' totals, all divided by the slice's total so the density integrates to 1 over the
// unit square (in units of grid cells; evaluate() multiplies by (nx-1)(ny-1)).
void PiecewiseLinear2D::build_cdfs(const float* data, uint32_t slices) {
  const size_t values = size_t(nx_) * ny_;
  data_.resize(slices * values);
  marginal_cdf_.resize(size_t(slices) * ny_);
  conditional_cdf_.resize(slices * values);
  for (uint32_t s = 0; s < slices; ++s) {
    const float* in = data + s * values;
    float* cond = conditional_cdf_.data() + s * values;
    float* marg = marginal_cdf_.data() + size_t(s) * ny_;
    for (int y = 0; y < ny_; ++y) {
      double sum = 0.0;
      size_t i = size_t(y) * nx_;
      cond[i] = 0.f;
      for (int x = 0; x < nx_ - 1; ++x, ++i) {
        sum += 0.5 * (double(in[i]) + double(in[i + 1]));
        cond[i + 1] = float(sum);
      }
    }
    marg[0] = 0.f;
    double sum = 0.0;
    for (int y = 0; y < ny_ - 1; ++y) {
      sum += 0.5 * (double(cond[size_t(y + 1) * nx_ - 1]) + double(cond[size_t(y + 2) * nx_ - 1]));
      marg[y + 1] = float(sum);
    }
    const float normalization = 1.f / marg[ny_ - 1];
    for (size_t i = 0; i < values; ++i) cond[i] *= normalization;
    for (int y = 0; y < ny_; ++y) marg[y] *= normalization;
    for (size_t i = 0; i < values; ++i) data_[s * values + i] = in[i] * normalization;
  }
}

PiecewiseLinear2D::Blend PiecewiseLinear2D::blend(const float* param) const {
  Blend b;
  b.n = 1;
  b.slice[0] = 0;
  b.weight[0] = 1.f;
  for (size_t d = 0; d < params_.size(); ++d) {
    const std::vector<float>& nodes = params_[d];
    if (nodes.size() == 1) continue;
    const float x = param[d];
    const uint32_t i = find_interval(uint32_t(nodes.size()), [&](uint32_t k) { return nodes[k] <= x; });
    const float w1 = std::clamp((x - nodes[i]) / (nodes[i + 1] - nodes[i]), 0.f, 1.f), w0 = 1.f - w1;
    // Each corner so far splits into the node below and the node above.
    for (int k = 0; k < b.n; ++k) {
      b.slice[b.n + k] = b.slice[k] + strides_[d] * (i + 1);
      b.weight[b.n + k] = b.weight[k] * w1;
      b.slice[k] += strides_[d] * i;
      b.weight[k] *= w0;
    }
    b.n *= 2;
  }
  return b;
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::sample(Vec2 u, const float* param) const {
  const Blend b = blend(param);
  const uint32_t size = uint32_t(nx_) * ny_, nx = uint32_t(nx_);
  // pbrt-v4 keeps the sample off 0 and 1 exactly.
  u.x = std::clamp(u.x, 1.f - kOneMinusEpsilon, kOneMinusEpsilon);
  u.y = std::clamp(u.y, 1.f - kOneMinusEpsilon, kOneMinusEpsilon);

  // The row, from the marginal CDF, then the position within it.
  auto marginal = [&](uint32_t i) { return lookup(marginal_cdf_, b, i, uint32_t(ny_)); };
  const uint32_t row = find_interval(uint32_t(ny_), [&](uint32_t i) { return marginal(i) < u.y; });
  u.y -= marginal(row);
  uint32_t offset = row * nx;
  const float r0 = lookup(conditional_cdf_, b, offset + nx - 1, size),
              r1 = lookup(conditional_cdf_, b, offset + 2 * nx - 1, size);
  u.y = invert_linear(u.y, r0, r1);

  // The column, from the conditional CDF interpolated at that height.
  u.x *= (1.f - u.y) * r0 + u.y * r1;
  auto conditional = [&](uint32_t i) {
    return (1.f - u.y) * lookup(conditional_cdf_, b, offset + i, size) +
           u.y * lookup(conditional_cdf_, b, offset + nx + i, size);
  };
  const uint32_t col = find_interval(nx, [&](uint32_t i) { return conditional(i) < u.x; });
  u.x -= conditional(col);
  offset += col;
  const float v00 = lookup(data_, b, offset, size), v10 = lookup(data_, b, offset + 1, size),
              v01 = lookup(data_, b, offset + nx, size), v11 = lookup(data_, b, offset + nx + 1, size);
  const float c0 = (1.f - u.y) * v00 + u.y * v01, c1 = (1.f - u.y) * v10 + u.y * v11;
  u.x = invert_linear(u.x, c0, c1);
  return {Vec2((col + u.x) / float(nx_ - 1), (row + u.y) / float(ny_ - 1)),
          ((1.f - u.x) * c0 + u.x * c1) * float(nx_ - 1) * float(ny_ - 1)};
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::invert(Vec2 p, const float* param) const {
  const Blend b = blend(param);
  const uint32_t size = uint32_t(nx_) * ny_, nx = uint32_t(nx_);
  p.x *= float(nx_ - 1);
  p.y *= float(ny_ - 1);
  const int px = cell(p.x, nx_), py = cell(p.y, ny_);
  p -= Vec2(float(px), float(py));
  uint32_t offset = uint32_t(px) + uint32_t(py) * nx;

  // The column position: the conditional CDF up to p.x at this height.
  const float v00 = lookup(data_, b, offset, size), v10 = lookup(data_, b, offset + 1, size),
              v01 = lookup(data_, b, offset + nx, size), v11 = lookup(data_, b, offset + nx + 1, size);
  const float c0 = (1.f - p.y) * v00 + p.y * v01, c1 = (1.f - p.y) * v10 + p.y * v11;
  const float pdf = (1.f - p.x) * c0 + p.x * c1;
  p.x *= c0 + 0.5f * p.x * (c1 - c0);
  p.x += (1.f - p.y) * lookup(conditional_cdf_, b, offset, size) + p.y * lookup(conditional_cdf_, b, offset + nx, size);
  offset = uint32_t(py) * nx;
  const float r0 = lookup(conditional_cdf_, b, offset + nx - 1, size),
              r1 = lookup(conditional_cdf_, b, offset + 2 * nx - 1, size);
  p.x /= (1.f - p.y) * r0 + p.y * r1;

  // The row position: the marginal CDF up to p.y.
  p.y *= r0 + 0.5f * p.y * (r1 - r0);
  p.y += lookup(marginal_cdf_, b, uint32_t(py), uint32_t(ny_));
  return {p, pdf * float(nx_ - 1) * float(ny_ - 1)};
}

float PiecewiseLinear2D::evaluate(Vec2 p, const float* param) const {
  const Blend b = blend(param);
  const uint32_t size = uint32_t(nx_) * ny_, nx = uint32_t(nx_);
  p.x *= float(nx_ - 1);
  p.y *= float(ny_ - 1);
  const int px = cell(p.x, nx_), py = cell(p.y, ny_);
  const Vec2 w1 = p - Vec2(float(px), float(py)), w0 = Vec2(1.f) - w1;
  const uint32_t i = uint32_t(px) + uint32_t(py) * nx;
  const float v00 = lookup(data_, b, i, size), v10 = lookup(data_, b, i + 1, size),
              v01 = lookup(data_, b, i + nx, size), v11 = lookup(data_, b, i + nx + 1, size);
  const float v = w0.y * (w0.x * v00 + w1.x * v10) + w1.y * (w0.x * v01 + w1.x * v11);
  // A warp stores the density in cell units; a plain table its own values.
  return marginal_cdf_.empty() ? v : v * float(nx_ - 1) * float(ny_ - 1);
}

}  // namespace eyetrace
