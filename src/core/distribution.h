// Piecewise-constant distributions on [0,1) and [0,1)^2, sampled by inverting their CDF
// (pbrt-v4 appendix A.4). Lights use them to pick directions in proportion to an
// environment map's brightness, and the light sampler to pick lights by power.
#pragma once
#include <optional>
#include <span>
#include <vector>

#include "core/math.h"

namespace eyetrace {

// A step function over n equal bins of [0,1).
class PiecewiseConstant1D {
 public:
  // One bin of zero: uniform.
  PiecewiseConstant1D();
  // Bin values should be non-negative; negative or non-finite values count as zero (a
  // density cannot be negative). An all-zero function (or an empty one, taken as a single
  // zero bin) is sampled uniformly, so nothing divides by its zero integral.
  explicit PiecewiseConstant1D(std::span<const float> f);

  // A continuous sample in [0,1), its density, and the bin it fell in.
  float sample(float u, float* pdf = nullptr, int* offset = nullptr) const;
  // A bin chosen with probability value/sum (1/n for an all-zero function).
  size_t sample_discrete(float u, float* pmf = nullptr) const;
  float pmf(size_t i) const;
  // Density of the continuous sample at x in [0,1) (0 outside).
  float pdf(float x) const;
  // The u that sample() maps to x; nullopt for x outside [0,1].
  std::optional<float> invert(float x) const;

  float integral() const { return integral_; }  // true integral: 0 for an all-zero function
  size_t size() const { return func_.size(); }
  float value(size_t i) const { return func_[i]; }

 private:
  size_t find_bin(float u) const;
  bool uniform() const { return !(integral_ > 0.f); }
  std::vector<float> func_;
  std::vector<float> cdf_;  // size n + 1, cdf_[0] = 0, cdf_[n] = 1
  float integral_ = 0.f;
  float sum_ = 0.f;
};

// A step function over nu x nv cells of [0,1)^2, stored row by row: f[v * nu + u].
// Samples the row (v) from the marginal, then the column (u) within that row.
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  // Throws std::invalid_argument unless f.size() == nu * nv with nu, nv > 0.
  PiecewiseConstant2D(std::span<const float> f, int nu, int nv);

  // A point in [0,1)^2 with its density (w.r.t. area in [0,1)^2).
  Vec2 sample(Vec2 u, float* pdf = nullptr, IVec2* cell = nullptr) const;
  float pdf(Vec2 p) const;
  std::optional<Vec2> invert(Vec2 p) const;
  float integral() const { return marginal_.integral(); }
  int nu() const { return nu_; }
  int nv() const { return nv_; }

 private:
  int nu_ = 0, nv_ = 0;
  std::vector<PiecewiseConstant1D> conditional_;  // one per row v
  PiecewiseConstant1D marginal_;                  // row integrals
};

}  // namespace eyetrace
