// The uniform grid over an SPPM iteration's visible points that photons look up (pbrt-v4's
// hashed grid): cells of about the largest search radius over the points' bounds, each listing
// the pixels whose search sphere's bounding box overlaps it. A photon then needs only the one
// cell it lands in. Built by one thread in pixel order, so the lists (and the order in which a
// photon meets the pixels) do not depend on the thread count.
#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "integrators/sppm_pixel.h"

namespace eyetrace {

class VisiblePointGrid {
 public:
  // Pixels with a visible point (vp.bsdf set) enter with their current radius.
  explicit VisiblePointGrid(const std::vector<SppmPixel>& pixels);
  bool empty() const { return entries_.empty(); }
  // Calls f(pixel index) for every pixel listed in p's cell; nothing when p is outside the grid.
  template <typename F>
  void for_each_candidate(const Vec3& p, F&& f) const {
    int c[3];
    if (empty() || !cell_of(p, c)) return;
    const size_t h = hash(c);
    for (uint32_t i = start_[h]; i < start_[h + 1]; ++i) f(entries_[i]);
  }
  int resolution(int axis) const { return res_[axis]; }

 private:
  // The cell containing p, clamped to the grid; false when p lies outside the grid's bounds.
  bool cell_of(const Vec3& p, int c[3]) const;
  size_t hash(const int c[3]) const;

  Bounds3 bounds_;
  int res_[3] = {1, 1, 1};
  std::vector<uint32_t> start_;    // per hash bucket, the first entry (size buckets + 1)
  std::vector<uint32_t> entries_;  // pixel indices, bucket by bucket, in pixel order
};

}  // namespace eyetrace
