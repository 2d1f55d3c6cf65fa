// Majorants: upper bounds on a medium's extinction along a ray, the densities delta and ratio
// tracking sample tentative collisions with (pbrt-v4's RayMajorantSegment, MajorantGrid and
// DDAMajorantIterator, PBR 4th ed. section 11.4). A segment [t_min, t_max) of a ray carries a
// constant sigma_maj >= sigma_t at every point of it; the iterator hands out the segments in
// order. A medium with one bound everywhere gives one segment; a grid medium gives one per
// voxel of a coarse grid of maxima that the ray crosses, walked by a 3-D DDA
// (Amanatides and Woo 1987), so thin regions of a dense medium are crossed in few steps.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct MajorantSegment {
  float t_min, t_max;
  SampledSpectrum sigma_maj;
};

// Maxima of a density over the voxels of a res^3 grid spanning `bounds` (the medium's space).
// Voxel (x, y, z) covers [x/res, (x+1)/res) of the unit cube along x, and so on. pbrt-v4 uses
// res 16 for its grids and 64 for NanoVDB volumes.
struct MajorantGrid {
  explicit MajorantGrid(int resolution = 16) : res(resolution), voxels(size_t(res) * res * res, 0.f) {}
  int res;
  Bounds3 bounds;
  std::vector<float> voxels;

  float lookup(int x, int y, int z) const { return voxels[x + res * (y + size_t(res) * z)]; }
  void set(int x, int y, int z, float v) { voxels[x + res * (y + size_t(res) * z)] = v; }
  // The voxel's extent in the unit cube of `bounds`.
  Bounds3 voxel_bounds(int x, int y, int z) const {
    Bounds3 b;
    b.lo = Vec3(float(x), float(y), float(z)) / float(res);
    b.hi = Vec3(float(x + 1), float(y + 1), float(z + 1)) / float(res);
    return b;
  }
};

// The parametric range [t0, t1] of o + t d inside box `b` clipped to [0, t_max]; nullopt when
// the ray misses it. Slabs per axis (a zero direction component gives +-inf slab distances,
// which min/max handle; an origin exactly on a slab with d 0 gives NaN, which the comparisons
// below treat as "no constraint", as pbrt-v4's Bounds3::IntersectP does).
inline std::optional<std::pair<float, float>> intersect_box(const Bounds3& b, const Vec3& o, const Vec3& d,
                                                            float t_max) {
  float t0 = 0.f, t1 = t_max;
  for (int i = 0; i < 3; ++i) {
    const float inv = 1.f / d[i];
    float t_near = (b.lo[i] - o[i]) * inv, t_far = (b.hi[i] - o[i]) * inv;
    if (t_near > t_far) std::swap(t_near, t_far);
    t_far *= 1.f + 2.f * 3.f * 0x1p-24f;  // pbrt-v4's gamma(3) widening: no gaps from rounding
    t0 = t_near > t0 ? t_near : t0;
    t1 = t_far < t1 ? t_far : t1;
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{t0, t1};
}

// Hands out the majorant segments of one ray: either a single segment (a medium with one bound)
// or the voxels of a MajorantGrid the ray crosses between t_min and t_max. `o` and `d` are the
// ray in the grid medium's space, with the same parameter t as the renderer's ray.
class MajorantIterator {
 public:
  MajorantIterator() = default;  // no segments: the ray misses the medium
  MajorantIterator(float t_min, float t_max, const SampledSpectrum& sigma_maj)
      : sigma_t_(sigma_maj), t_min_(t_min), t_max_(t_max) {}
  MajorantIterator(const Vec3& o, const Vec3& d, float t_min, float t_max, const MajorantGrid* grid,
                   const SampledSpectrum& sigma_t)
      : sigma_t_(sigma_t), t_min_(t_min), t_max_(t_max), grid_(grid) {
    const Vec3 diag = grid->bounds.hi - grid->bounds.lo;
    const Vec3 o_grid = (o - grid->bounds.lo) / diag;
    Vec3 d_grid = d / diag;
    const Vec3 p = o_grid + t_min * d_grid;
    const int n = grid->res;
    for (int a = 0; a < 3; ++a) {
      voxel_[a] = std::clamp(int(p[a] * n), 0, n - 1);
      delta_t_[a] = 1.f / (std::abs(d_grid[a]) * n);  // inf for d 0: never stepped along
      if (d_grid[a] == -0.f) d_grid[a] = 0.f;         // -0 would step the wrong way
      if (d_grid[a] >= 0.f) {
        next_t_[a] = t_min + (float(voxel_[a] + 1) / n - p[a]) / d_grid[a];
        step_[a] = 1;
        limit_[a] = n;
      } else {
        next_t_[a] = t_min + (float(voxel_[a]) / n - p[a]) / d_grid[a];
        step_[a] = -1;
        limit_[a] = -1;
      }
    }
  }

  std::optional<MajorantSegment> next() {
    if (!(t_min_ < t_max_)) return std::nullopt;
    if (!grid_) {
      const MajorantSegment seg{t_min_, t_max_, sigma_t_};
      t_min_ = t_max_;
      return seg;
    }
    // The axis whose voxel boundary comes first (pbrt-v4's comparison table).
    const int bits = ((next_t_[0] < next_t_[1]) << 2) + ((next_t_[0] < next_t_[2]) << 1) + (next_t_[1] < next_t_[2]);
    constexpr int kCmpToAxis[8] = {2, 1, 2, 1, 2, 2, 0, 0};
    const int axis = kCmpToAxis[bits];
    const float t_exit = std::min(t_max_, next_t_[axis]);
    const MajorantSegment seg{t_min_, t_exit, sigma_t_ * grid_->lookup(voxel_[0], voxel_[1], voxel_[2])};
    t_min_ = next_t_[axis] > t_max_ ? t_max_ : t_exit;
    voxel_[axis] += step_[axis];
    if (voxel_[axis] == limit_[axis]) t_min_ = t_max_;
    next_t_[axis] += delta_t_[axis];
    return seg;
  }

 private:
  SampledSpectrum sigma_t_;  // single segment: its majorant; grid: multiplies the voxel maxima
  float t_min_ = 1.f, t_max_ = 0.f;
  const MajorantGrid* grid_ = nullptr;
  float next_t_[3] = {0.f, 0.f, 0.f}, delta_t_[3] = {0.f, 0.f, 0.f};
  int step_[3] = {0, 0, 0}, limit_[3] = {0, 0, 0}, voxel_[3] = {0, 0, 0};
};

}  // namespace eyetrace
