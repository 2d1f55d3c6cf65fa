// How far a render has got: for every 16x16 tile of the film, the number of samples per
// pixel it holds. A tile with count n holds sample indices [0, n) of each of its pixels,
// summed in index order, which is what makes a stopped-and-resumed render bit-identical to
// an uninterrupted one (the film's per-pixel sums see the same additions in the same order).
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
  int min_done() const { return done.empty() ? 0 : *std::min_element(done.begin(), done.end()); }
  int max_done() const { return done.empty() ? 0 : *std::max_element(done.begin(), done.end()); }
  // Camera samples the film holds in all.
  uint64_t samples(const PixelBounds& b) const {
    uint64_t n = 0;
    for (size_t t = 0; t < done.size(); ++t) n += uint64_t(tile_bounds(t, b).area()) * uint64_t(done[t]);
    return n;
  }
};

}  // namespace eyetrace
