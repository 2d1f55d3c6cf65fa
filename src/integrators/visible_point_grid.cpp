#include "integrators/visible_point_grid.h"

#include <algorithm>

namespace eyetrace {

namespace {

// The cell range a visible point's search sphere overlaps.
struct CellRange {
  int lo[3], hi[3];
};

}  // namespace

VisiblePointGrid::VisiblePointGrid(const std::vector<SppmPixel>& pixels) {
  double max_radius = 0;
  for (const SppmPixel& px : pixels) {
    if (!px.vp.bsdf) continue;
    const Vec3 r(float(px.radius));
    bounds_.extend(px.vp.p - r);
    bounds_.extend(px.vp.p + r);
    max_radius = std::max(max_radius, px.radius);
  }
  start_.assign(std::max<size_t>(pixels.size(), 1) + 1, 0);
  if (bounds_.empty() || !(max_radius > 0)) return;
  // Cells about the largest radius wide (pbrt-v4): a photon's cell then lists every point
  // within reach, and a point enters at most a few cells per axis.
  const Vec3 diag = bounds_.hi - bounds_.lo;
  const float max_diag = std::max({diag.x, diag.y, diag.z});
  const int base = int(std::clamp(double(max_diag) / max_radius, 1.0, 1024.0));
  for (int a = 0; a < 3; ++a) res_[a] = std::max(int(base * diag[a] / max_diag), 1);

  // Two passes (count, then fill) make the bucket lists one array. A point enters each bucket
  // once, even when several of its cells hash to the same bucket: listed twice, it would
  // receive a photon in such a cell twice (pbrt-v4 lists it per cell and does).
  std::vector<size_t> buckets;
  auto visit = [&](auto&& f) {
    for (size_t i = 0; i < pixels.size(); ++i) {
      const SppmPixel& px = pixels[i];
      if (!px.vp.bsdf) continue;
      const Vec3 r(float(px.radius));
      CellRange cr;
      cell_of(px.vp.p - r, cr.lo);
      cell_of(px.vp.p + r, cr.hi);
      buckets.clear();
      for (int z = cr.lo[2]; z <= cr.hi[2]; ++z)
        for (int y = cr.lo[1]; y <= cr.hi[1]; ++y)
          for (int x = cr.lo[0]; x <= cr.hi[0]; ++x) {
            const int c[3] = {x, y, z};
            buckets.push_back(hash(c));
          }
      std::sort(buckets.begin(), buckets.end());
      buckets.erase(std::unique(buckets.begin(), buckets.end()), buckets.end());
      for (size_t h : buckets) f(h, uint32_t(i));
    }
  };
  visit([&](size_t h, uint32_t) { ++start_[h + 1]; });
  for (size_t h = 1; h < start_.size(); ++h) start_[h] += start_[h - 1];
  entries_.resize(start_.back());
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  visit([&](size_t h, uint32_t i) { entries_[fill[h]++] = i; });
}

bool VisiblePointGrid::cell_of(const Vec3& p, int c[3]) const {
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    const float extent = bounds_.hi[a] - bounds_.lo[a];
    const float t = extent > 0.f ? (p[a] - bounds_.lo[a]) / extent : 0.f;
    // A NaN position fails both comparisons and is outside.
    const bool in = t >= 0.f && t <= 1.f;
    inside &= in;
    c[a] = in ? std::min(int(t * float(res_[a])), res_[a] - 1) : (t > 1.f ? res_[a] - 1 : 0);
  }
  return inside;
}

size_t VisiblePointGrid::hash(const int c[3]) const {
  // pbrt-v4's spatial hash (Teschner et al. 2003), over as many buckets as pixels.
  const uint32_t h = (uint32_t(c[0]) * 73856093u) ^ (uint32_t(c[1]) * 19349663u) ^ (uint32_t(c[2]) * 83492791u);
  return size_t(h) % (start_.size() - 1);
}

}  // namespace eyetrace
