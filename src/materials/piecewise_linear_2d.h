// A function tabulated on a regular nx x ny grid over [0, 1]^2 and interpolated bilinearly,
// optionally one per node of up to three parameters (interpolated linearly between nodes): the
// interpolant behind the RGL measured BRDFs (Dupuy & Jakob 2018, "An adaptive parameterization
// for efficient material acquisition and rendering"), with the arithmetic of pbrt-v4's
// PiecewiseLinear2D<N> (util/sampling.h), so that a `measured` material samples and evaluates
// what pbrt-v4 does. As a warp (`warp` true) the table is a density: it is normalised to
// integrate to 1 and sampled by inverting its marginal (rows) and conditional (columns) CDFs,
// each piece being linear; invert() is sample()'s inverse. Otherwise evaluate() returns the
// table's own values, interpolated.
//
// Requirements (checked by the caller, the tensor-file reader): nx, ny >= 2, finite values, a
// warp's values non-negative with positive mass in every slice, parameter nodes increasing.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace eyetrace {

class PiecewiseLinear2D {
 public:
  static constexpr int kMaxParams = 3;
  struct Sample {
    Vec2 p;
    float pdf;
  };

  PiecewiseLinear2D() = default;
  // `data`: one nx x ny table (x fastest) per combination of parameter nodes, the last
  // parameter varying fastest; `params`: each parameter's node values.
  PiecewiseLinear2D(const float* data, int nx, int ny, std::vector<std::vector<float>> params, bool warp);

  // `param` holds one value per parameter (outside the nodes: the end slice).
  Sample sample(Vec2 u, const float* param) const;
  Sample invert(Vec2 p, const float* param) const;
  float evaluate(Vec2 p, const float* param) const;

 private:
  // The slices around a parameter point and their weights (2^k corners for k parameters
  // with more than one node).
  struct Blend {
    std::array<uint32_t, 1u << kMaxParams> slice{};
    std::array<float, 1u << kMaxParams> weight{};
    int n = 0;
  };
  Blend blend(const float* param) const;
  // The blended value at `index` within a slice of `slice_size` values.
  static float lookup(const std::vector<float>& v, const Blend& b, uint32_t index, uint32_t slice_size) {
    float sum = 0.f;
    for (int k = 0; k < b.n; ++k) sum += b.weight[k] * v[size_t(b.slice[k]) * slice_size + index];
    return sum;
  }
  void build_cdfs(const float* data, uint32_t slices);

  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<float>> params_;
  std::vector<uint32_t> strides_;  // slices between neighbouring nodes of each parameter
  std::vector<float> data_, marginal_cdf_, conditional_cdf_;
};

// pbrt-v4's FindInterval: the largest i in [0, size - 2] with pred(i) true (pred monotone,
// true then false), by bisection.
template <typename Pred>
inline uint32_t find_interval(uint32_t size, const Pred& pred) {
  int64_t n = int64_t(size) - 2, first = 1;
  while (n > 0) {
    int64_t half = n >> 1, middle = first + half;
    bool r = pred(uint32_t(middle));
    first = r ? middle + 1 : first;
    n = r ? n - (half + 1) : half;
  }
  return uint32_t(std::clamp<int64_t>(first - 1, 0, int64_t(size) - 2));
}

}  // namespace eyetrace
