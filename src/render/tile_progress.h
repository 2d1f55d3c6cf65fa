// How far a render has got: for every 16x16 tile of the film, the number of samples per
// pixel it holds. A tile with count n holds sample indices [0, n) of each of its pixels,
// summed in index order, which is what makes a stopped-and-resumed render bit-identical to
// an uninterrupted one (the film's per-pixel sums see the same additions in the same order).
//
// An adaptive render (render/adaptive_sampling.h) counts per pixel instead: pixel p holds
// sample indices [0, pixel_done[p]) and the pass under way takes it to pixel_target[p]; a
// tile is finished with the pass when all its pixels have reached their targets.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/film.h"

namespace eyetrace {

struct TileProgress {
  static constexpr int kTileSize = 16;
  IVec2 tiles{0};         // tile grid over the film's pixel bounds
  std::vector<int> done;  // samples per pixel held, per tile, row-major
  // Adaptive renders only (empty otherwise): per pixel of the bounds, row-major.
  std::vector<int> pixel_done, pixel_target;

  bool adaptive() const { return !pixel_done.empty(); }

  static TileProgress start(const PixelBounds& b) {
    TileProgress p;
    p.tiles = IVec2((b.width() + kTileSize - 1) / kTileSize, (b.height() + kTileSize - 1) / kTileSize);
    p.done.assign(size_t(p.tiles.x) * p.tiles.y, 0);
    return p;
  }
  bool matches(const PixelBounds& b) const {
    TileProgress s = start(b);
    return s.tiles == tiles && s.done.size() == done.size();
  }
  // The pixels of tile t (absolute raster coordinates, [lo, hi)).
  PixelBounds tile_bounds(size_t t, const PixelBounds& b) const {
    PixelBounds r;
    r.lo = b.lo + IVec2(int(t % tiles.x), int(t / tiles.x)) * kTileSize;
    r.hi = glm::min(r.lo + IVec2(kTileSize), b.hi);
    return r;
  }
  // The fewest and most samples any pixel holds.
  int min_done() const { return min_of(adaptive() ? pixel_done : done); }
  int max_done() const { return max_of(adaptive() ? pixel_done : done); }
  // Every pixel has all the samples it will get: `spp` each, or, adaptive, its target with no
  // pass planned beyond it.
  bool complete(int spp) const { return adaptive() ? pixel_done == pixel_target : min_done() >= spp; }
  // The samples each pixel holds, row-major over the bounds.
  std::vector<int> pixel_counts(const PixelBounds& b) const {
    if (adaptive()) return pixel_done;
    std::vector<int> n(b.area());
    for (size_t t = 0; t < done.size(); ++t) {
      const PixelBounds tb = tile_bounds(t, b);
      for (int y = tb.lo.y; y < tb.hi.y; ++y)
        for (int x = tb.lo.x; x < tb.hi.x; ++x)
          n[size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x)] = done[t];
    }
    return n;
  }
  // Camera samples the film holds in all.
  uint64_t samples(const PixelBounds& b) const {
    uint64_t n = 0;
    if (adaptive()) {
      for (int d : pixel_done) n += uint64_t(d);
      return n;
    }
    for (size_t t = 0; t < done.size(); ++t) n += uint64_t(tile_bounds(t, b).area()) * uint64_t(done[t]);
    return n;
  }

 private:
  static int min_of(const std::vector<int>& v) { return v.empty() ? 0 : *std::min_element(v.begin(), v.end()); }
  static int max_of(const std::vector<int>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }
};

}  // namespace eyetrace
