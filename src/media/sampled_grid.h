// Values on a regular nx x ny x nz lattice over the unit cube, reconstructed trilinearly, as
// pbrt-v4's SampledGrid: sample (x, y, z) sits at the centre of its cell, ((x + 0.5) / nx,
// ...), and samples outside the lattice count as zero, so a grid fades to nothing over the
// outer half cell. Values are stored x fastest, then y, then z (pbrt-v4's order, the order of
// a "density" parameter's numbers).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math.h"

namespace eyetrace {

template <typename T>
class SampledGrid {
 public:
  SampledGrid() = default;
  SampledGrid(std::vector<T> values, int nx, int ny, int nz) : values_(std::move(values)), nx_(nx), ny_(ny), nz_(nz) {}

  bool empty() const { return values_.empty(); }

  // The sample at lattice point (x, y, z), T{} (zero) outside the lattice.
  const T& at(int x, int y, int z) const {
    static const T zero{};
    if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return zero;
    return values_[(size_t(z) * ny_ + y) * nx_ + x];
  }

  // Trilinear interpolation at p in the unit cube of the grid's bounds; `convert` maps a
  // sample to what is interpolated (a spectrum at the path's wavelengths, say).
  template <typename F>
  auto lookup(const Vec3& p, F convert) const {
    const Vec3 s(p.x * nx_ - 0.5f, p.y * ny_ - 0.5f, p.z * nz_ - 0.5f);
    const Vec3 f = glm::floor(s);
    const int x = int(f.x), y = int(f.y), z = int(f.z);
    const Vec3 d = s - f;
    auto lerp = [](float t, const auto& a, const auto& b) { return (1.f - t) * a + t * b; };
    auto c = [&](int dx, int dy, int dz) { return convert(at(x + dx, y + dy, z + dz)); };
    const auto d00 = lerp(d.x, c(0, 0, 0), c(1, 0, 0)), d10 = lerp(d.x, c(0, 1, 0), c(1, 1, 0));
    const auto d01 = lerp(d.x, c(0, 0, 1), c(1, 0, 1)), d11 = lerp(d.x, c(0, 1, 1), c(1, 1, 1));
    return lerp(d.z, lerp(d.y, d00, d10), lerp(d.y, d01, d11));
  }
  T lookup(const Vec3& p) const {
    return lookup(p, [](const T& v) { return v; });
  }

  // The largest `value(sample)` of the samples whose interpolation reaches into `b` (a box
  // in the unit cube): a trilinear interpolation never exceeds its corners, so this bounds
  // every lookup inside b (pbrt-v4's SampledGrid::MaxValue).
  template <typename F>
  float max_value(const Bounds3& b, F value) const {
    const int x0 = std::max(int(std::floor(b.lo.x * nx_ - 0.5f)), 0);
    const int y0 = std::max(int(std::floor(b.lo.y * ny_ - 0.5f)), 0);
    const int z0 = std::max(int(std::floor(b.lo.z * nz_ - 0.5f)), 0);
    const int x1 = std::min(int(std::floor(b.hi.x * nx_ - 0.5f)) + 1, nx_ - 1);
    const int y1 = std::min(int(std::floor(b.hi.y * ny_ - 0.5f)) + 1, ny_ - 1);
    const int z1 = std::min(int(std::floor(b.hi.z * nz_ - 0.5f)) + 1, nz_ - 1);
    float m = value(at(x0, y0, z0));
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) m = std::max(m, value(at(x, y, z)));
    return m;
  }

 private:
  std::vector<T> values_;
  int nx_ = 0, ny_ = 0, nz_ = 0;
};

}  // namespace eyetrace
