#include "core/distribution.h"

#include <algorithm>
#include <stdexcept>

namespace eyetrace {

PiecewiseConstant1D::PiecewiseConstant1D() : func_(1, 0.f), cdf_{0.f, 1.f} {}

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> f) {
  func_.reserve(std::max<size_t>(f.size(), 1));
  for (float v : f) func_.push_back(std::isfinite(v) && v > 0.f ? v : 0.f);
  if (func_.empty()) func_.push_back(0.f);
  size_t n = func_.size();

  // Running sums in double: a float CDF over thousands of bins would lose the small ones.
  std::vector<double> running(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) running[i + 1] = running[i] + func_[i];
  double total = running[n];
  sum_ = float(total);
  integral_ = float(total / double(n));

  cdf_.resize(n + 1);
  for (size_t i = 0; i <= n; ++i) cdf_[i] = total > 0.0 ? float(running[i] / total) : float(double(i) / double(n));
  cdf_[n] = 1.f;
}

// The last bin whose CDF start is <= u; zero-width bins are skipped because a later bin
// with the same start wins.
size_t PiecewiseConstant1D::find_bin(float u) const {
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
  size_t i = it == cdf_.begin() ? 0 : size_t(it - cdf_.begin()) - 1;
  return std::min(i, func_.size() - 1);
}

float PiecewiseConstant1D::sample(float u, float* pdf, int* offset) const {
  size_t o = find_bin(u);
  if (offset) *offset = int(o);
  float du = u - cdf_[o];
  float width = cdf_[o + 1] - cdf_[o];
  if (width > 0.f) du /= width;
  if (pdf) *pdf = uniform() ? 1.f : func_[o] / integral_;
  float x = (float(o) + std::clamp(du, 0.f, 1.f)) / float(func_.size());
  return std::min(x, kOneMinusEpsilon);
}

size_t PiecewiseConstant1D::sample_discrete(float u, float* pmf_out) const {
  size_t o = find_bin(u);
  if (pmf_out) *pmf_out = pmf(o);
  return o;
}

float PiecewiseConstant1D::pmf(size_t i) const {
  if (i >= func_.size()) return 0.f;
  return uniform() ? 1.f / float(func_.size()) : func_[i] / sum_;
}

float PiecewiseConstant1D::pdf(float x) const {
  if (!(x >= 0.f && x < 1.f)) return 0.f;
  size_t o = std::min(size_t(x * float(func_.size())), func_.size() - 1);
  return uniform() ? 1.f : func_[o] / integral_;
}

std::optional<float> PiecewiseConstant1D::invert(float x) const {
  if (!(x >= 0.f && x <= 1.f)) return std::nullopt;
  float c = x * float(func_.size());
  size_t o = std::min(size_t(c), func_.size() - 1);
  float delta = c - float(o);
  return cdf_[o] + delta * (cdf_[o + 1] - cdf_[o]);
}

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> f, int nu, int nv) : nu_(nu), nv_(nv) {
  if (nu <= 0 || nv <= 0 || f.size() != size_t(nu) * size_t(nv))
    throw std::invalid_argument("PiecewiseConstant2D: function size does not match nu * nv");
  conditional_.reserve(nv);
  std::vector<float> row_integrals(nv);
  for (int v = 0; v < nv; ++v) {
    conditional_.emplace_back(f.subspan(size_t(v) * nu, nu));
    row_integrals[v] = conditional_.back().integral();
  }
  marginal_ = PiecewiseConstant1D(row_integrals);
}

Vec2 PiecewiseConstant2D::sample(Vec2 u, float* pdf, IVec2* cell) const {
  float pdf_v = 0.f, pdf_u = 0.f;
  int v = 0, iu = 0;
  float d1 = marginal_.sample(u.y, &pdf_v, &v);
  float d0 = conditional_[v].sample(u.x, &pdf_u, &iu);
  if (pdf) *pdf = pdf_u * pdf_v;
  if (cell) *cell = IVec2(iu, v);
  return Vec2(d0, d1);
}

float PiecewiseConstant2D::pdf(Vec2 p) const {
  if (!(p.x >= 0.f && p.x < 1.f && p.y >= 0.f && p.y < 1.f)) return 0.f;
  int iv = std::min(int(p.y * float(nv_)), nv_ - 1);
  // Same product as sample(): the all-zero map is uniform, an all-zero row never chosen.
  float pdf_v = marginal_.pmf(size_t(iv)) * float(nv_);
  float pdf_u = conditional_[iv].pdf(p.x);
  return pdf_u * pdf_v;
}

std::optional<Vec2> PiecewiseConstant2D::invert(Vec2 p) const {
  std::optional<float> v_inv = marginal_.invert(p.y);
  if (!v_inv) return std::nullopt;
  int iv = std::clamp(int(p.y * float(nv_)), 0, nv_ - 1);
  std::optional<float> u_inv = conditional_[iv].invert(p.x);
  if (!u_inv) return std::nullopt;
  return Vec2(*u_inv, *v_inv);
}

}  // namespace eyetrace
