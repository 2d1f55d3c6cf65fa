#include "core/catmull_rom.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace eyetrace {

namespace {

// The largest i in [0, size - 2] with pred(i) true (pred monotone: true then false), as
// pbrt-v4's FindInterval: a value below the first node maps to interval 0, above the last to
// the last interval.
template <typename Pred>
int find_interval(int size, const Pred& pred) {
  int first = 1, n = size - 2;
  while (n > 0) {
    const int half = n >> 1, middle = first + half;
    if (pred(middle)) {
      first = middle + 1;
      n -= half + 1;
    } else {
      n = half;
    }
  }
  return std::clamp(first - 1, 0, size - 2);
}

// A root of f in [x0, x1] where f changes sign, by Newton steps kept inside a shrinking
// bracket (bisection when a step leaves it). f returns (value, derivative).
template <typename F>
float newton_bisection(float x0, float x1, const F& f, float x_eps = 1e-6f, float f_eps = 1e-6f) {
  const float fx0 = f(x0).first, fx1 = f(x1).first;
  if (std::abs(fx0) < f_eps) return x0;
  if (std::abs(fx1) < f_eps) return x1;
  const bool start_negative = fx0 < 0.f;
  float mid = x0 + (x1 - x0) * -fx0 / (fx1 - fx0);
  for (int iter = 0; iter < 100; ++iter) {
    if (!(x0 < mid && mid < x1)) mid = 0.5f * (x0 + x1);
    const std::pair<float, float> fm = f(mid);
    if (start_negative == (fm.first < 0.f))
      x0 = mid;
    else
      x1 = mid;
    if (x1 - x0 < x_eps || std::abs(fm.first) < f_eps) return mid;
    mid -= fm.first / fm.second;
  }
  return 0.5f * (x0 + x1);  // not converged in 100 steps (never seen): the bracket's middle
}

// Finite-difference end derivatives of segment i (scaled to the segment's width).
std::pair<float, float> segment_slopes(std::span<const float> x, std::span<const float> f, int i) {
  const float width = x[i + 1] - x[i];
  const float d0 = i > 0 ? width * (f[i + 1] - f[i - 1]) / (x[i + 1] - x[i - 1]) : f[i + 1] - f[i];
  const float d1 = i + 2 < int(x.size()) ? width * (f[i + 2] - f[i]) / (x[i + 2] - x[i]) : f[i + 1] - f[i];
  return {d0, d1};
}

}  // namespace

bool catmull_rom_weights(std::span<const float> nodes, float x, int* offset, float weights[4]) {
  if (!(x >= nodes.front() && x <= nodes.back())) return false;
  const int n = int(nodes.size());
  const int idx = find_interval(n, [&](int i) { return nodes[i] <= x; });
  *offset = idx - 1;
  const float x0 = nodes[idx], x1 = nodes[idx + 1];
  const float t = (x - x0) / (x1 - x0), t2 = t * t, t3 = t2 * t;
  weights[1] = 2 * t3 - 3 * t2 + 1;
  weights[2] = -2 * t3 + 3 * t2;
  if (idx > 0) {
    const float w0 = (t3 - 2 * t2 + t) * (x1 - x0) / (x1 - nodes[idx - 1]);
    weights[0] = -w0;
    weights[2] += w0;
  } else {
    const float w0 = t3 - 2 * t2 + t;
    weights[0] = 0;
    weights[1] -= w0;
    weights[2] += w0;
  }
  if (idx + 2 < n) {
    const float w3 = (t3 - t2) * (x1 - x0) / (nodes[idx + 2] - x0);
    weights[1] -= w3;
    weights[3] = w3;
  } else {
    const float w3 = t3 - t2;
    weights[1] -= w3;
    weights[2] += w3;
    weights[3] = 0;
  }
  return true;
}

float catmull_rom(std::span<const float> nodes, std::span<const float> f, float x) {
  if (!(x >= nodes.front() && x <= nodes.back())) return 0.f;
  const int idx = find_interval(int(nodes.size()), [&](int i) { return nodes[i] <= x; });
  const auto [d0, d1] = segment_slopes(nodes, f, idx);
  const float t = (x - nodes[idx]) / (nodes[idx + 1] - nodes[idx]), t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f[idx] + (-2 * t3 + 3 * t2) * f[idx + 1] + (t3 - 2 * t2 + t) * d0 + (t3 - t2) * d1;
}

float invert_catmull_rom(std::span<const float> nodes, std::span<const float> f, float u) {
  if (!(u > f.front())) return nodes.front();
  if (!(u < f.back())) return nodes.back();
  const int i = find_interval(int(f.size()), [&](int k) { return f[k] <= u; });
  const float f0 = f[i], f1 = f[i + 1], width = nodes[i + 1] - nodes[i];
  const auto [d0, d1] = segment_slopes(nodes, f, i);
  auto eval = [&](float t) {
    const float t2 = t * t, t3 = t2 * t;
    const float F = (2 * t3 - 3 * t2 + 1) * f0 + (-2 * t3 + 3 * t2) * f1 + (t3 - 2 * t2 + t) * d0 + (t3 - t2) * d1;
    const float dF = (6 * t2 - 6 * t) * f0 + (-6 * t2 + 6 * t) * f1 + (3 * t2 - 4 * t + 1) * d0 + (3 * t2 - 2 * t) * d1;
    return std::pair{F - u, dF};
  };
  return nodes[i] + newton_bisection(0.f, 1.f, eval) * width;
}

float integrate_catmull_rom(std::span<const float> nodes, std::span<const float> f, std::span<float> cdf) {
  float sum = 0.f;
  cdf[0] = 0.f;
  for (int i = 0; i + 1 < int(nodes.size()); ++i) {
    const auto [d0, d1] = segment_slopes(nodes, f, i);
    sum += (nodes[i + 1] - nodes[i]) * ((f[i] + f[i + 1]) / 2 + (d0 - d1) / 12);
    cdf[i + 1] = sum;
  }
  return sum;
}

float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2, std::span<const float> values,
                            std::span<const float> cdf, float alpha, float u, float* fval, float* pdf) {
  int offset;
  float weights[4];
  if (!catmull_rom_weights(nodes1, alpha, &offset, weights)) return nodes2.front();
  const int n2 = int(nodes2.size());
  auto interpolate = [&](std::span<const float> array, int idx) {
    float v = 0.f;
    for (int i = 0; i < 4; ++i)
      if (weights[i] != 0.f) v += array[(offset + i) * n2 + idx] * weights[i];
    return v;
  };
  const float maximum = interpolate(cdf, n2 - 1);
  u *= maximum;
  const int idx = find_interval(n2, [&](int i) { return interpolate(cdf, i) <= u; });
  const float f0 = interpolate(values, idx), f1 = interpolate(values, idx + 1);
  const float x0 = nodes2[idx], x1 = nodes2[idx + 1], width = x1 - x0;
  u = (u - interpolate(cdf, idx)) / width;
  const float d0 = idx > 0 ? width * (f1 - interpolate(values, idx - 1)) / (x1 - nodes2[idx - 1]) : f1 - f0;
  const float d1 = idx + 2 < n2 ? width * (interpolate(values, idx + 2) - f0) / (nodes2[idx + 2] - x0) : f1 - f0;
  // The segment's integral from 0 to t and its derivative, as polynomials in t.
  float fhat = 0.f;
  auto eval = [&](float t) {
    const float F = t * (f0 + t * (0.5f * d0 + t * ((1.f / 3.f) * (-2 * d0 - d1) + f1 - f0 +
                                                    t * (0.25f * (d0 + d1) + 0.5f * (f0 - f1)))));
    fhat = f0 + t * (d0 + t * (-2 * d0 - d1 + 3 * (f1 - f0) + t * (d0 + d1 + 2 * (f0 - f1))));
    return std::pair{F - u, fhat};
  };
  const float t = newton_bisection(0.f, 1.f, eval);
  if (fval) *fval = fhat;
  if (pdf) *pdf = fhat / maximum;
  return x0 + width * t;
}

}  // namespace eyetrace
