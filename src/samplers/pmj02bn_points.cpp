#include "samplers/pmj02bn_points.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "samplers/rng.h"

namespace eyetrace {

namespace {

uint32_t top_bits(uint32_t v, int b) { return b == 0 ? 0u : v >> (32 - b); }

// Which elementary intervals of a 2^M-point net the points so far occupy: one flag per
// interval of each of the M + 1 shapes 2^-a x 2^-(M-a), indexed by the top a bits of x and
// the top M - a bits of y.
class IntervalOccupancy {
 public:
  explicit IntervalOccupancy(int levels) : m_(levels), flags_(size_t(levels + 1) << levels, 0) {}
  bool occupied(int a, uint32_t x_top, uint32_t y_top) const { return flags_[index(a, x_top, y_top)] != 0; }
  void add(const std::array<uint32_t, 2>& p) {
    for (int a = 0; a <= m_; ++a) flags_[index(a, top_bits(p[0], a), top_bits(p[1], m_ - a))] = 1;
  }

 private:
  size_t index(int a, uint32_t x_top, uint32_t y_top) const {
    return (size_t(a) << m_) | (size_t(x_top) << (m_ - a)) | y_top;
  }
  int m_;
  std::vector<uint8_t> flags_;
};

// The points so far on a toroidal grid of 2^ceil(M/2) cells a side. A cell lies inside one
// elementary interval of shape 2^-ceil(M/2) x 2^-floor(M/2), and the points are part of a
// (0,M,2)-net, so a cell holds at most one point: one index per cell is enough.
class PointGrid {
 public:
  explicit PointGrid(int levels) : bits_((levels + 1) / 2), side_(1 << bits_), cells_(size_t(side_) * side_, -1) {}
  void add(int32_t index, const std::array<uint32_t, 2>& p) { cells_[cell(p)] = index; }

  // Squared toroidal distance from q to the nearest point, searched ring by ring around q's
  // cell until the next ring cannot be nearer; gives up (returning a value at most
  // `not_above`) as soon as a point is found within it, since the caller then rejects q.
  double min_distance2(const Pmj02Points& points, const std::array<uint32_t, 2>& q, double not_above) const {
    const double qx = q[0] * 0x1p-32, qy = q[1] * 0x1p-32, cell_side = 1.0 / side_;
    const int cx = int(top_bits(q[0], bits_)), cy = int(top_bits(q[1], bits_));
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r <= side_ / 2 + 1; ++r) {
      // Every point of ring r is at least (r - 1) cells away in x or in y.
      const double gap = (r - 1) * cell_side;
      if (r > 1 && gap * gap >= best) break;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; dx += (dy == -r || dy == r) ? 1 : 2 * r) {
          const int32_t i = cells_[size_t((cx + dx) & (side_ - 1)) + size_t((cy + dy) & (side_ - 1)) * side_];
          if (i < 0) continue;
          best = std::min(best, toroidal_distance2(qx, qy, points[size_t(i)]));
          if (best <= not_above) return best;
        }
    }
    return best;
  }

 private:
  size_t cell(const std::array<uint32_t, 2>& p) const {
    return size_t(top_bits(p[0], bits_)) + size_t(top_bits(p[1], bits_)) * side_;
  }
  static double toroidal_distance2(double qx, double qy, const std::array<uint32_t, 2>& p) {
    double dx = std::abs(qx - p[0] * 0x1p-32), dy = std::abs(qy - p[1] * 0x1p-32);
    dx = std::min(dx, 1.0 - dx);
    dy = std::min(dy, 1.0 - dy);
    return dx * dx + dy * dy;
  }
  int bits_, side_;
  std::vector<int32_t> cells_;
};

// A sub-quadrant (cell of side 2^-f) that a new point of the doubling may take: the top f
// bits of x and of y.
struct Slot {
  uint32_t x, y;
};

// The valid fine strata (top M bits of x, and of y) of a new point in sub-quadrant s. Shape a
// asks for the top a bits of x and the top M - a bits of y to name an empty interval. In both
// steps of the construction f = ceil(M/2), so for a <= f the x bits are the sub-quadrant's and
// shape a constrains only y, and for a >= M - f it constrains only x: the valid positions are
// the product of the valid x strata and the valid y strata. Each is found by a depth-first
// descent over the free bits, pruned at the first occupied interval.
struct ValidStrata {
  std::vector<uint32_t> x, y;
  bool empty() const { return x.empty() || y.empty(); }
};

class StrataSearch {
 public:
  StrataSearch(const IntervalOccupancy& occ, int m) : occ_(occ), m_(m), f_((m + 1) / 2) {}

  ValidStrata operator()(Slot s) const {
    ValidStrata v;
    // The shapes both coordinates' fixed bits name: the sub-quadrant's own intervals.
    for (int a = m_ - f_; a <= f_; ++a)
      if (occ_.occupied(a, s.x >> (f_ - a), s.y >> (f_ - (m_ - a)))) return v;
    descend_x(s, s.x, f_, v.x);
    if (!v.x.empty()) descend_y(s, s.y, m_ - f_, v.y);
    return v;
  }

 private:
  // x_top: the top a bits of x (a > f: the shape's y bits, M - a < f, are the sub-quadrant's).
  void descend_x(Slot s, uint32_t x_top, int a, std::vector<uint32_t>& out) const {
    if (a == m_) return out.push_back(x_top);
    for (uint32_t b = 0; b < 2; ++b) {
      const uint32_t x = (x_top << 1) | b;
      if (!occ_.occupied(a + 1, x, s.y >> (f_ - (m_ - a - 1)))) descend_x(s, x, a + 1, out);
    }
  }
  // y_top: the top M - a bits of y, for shapes a < M - f (whose x bits are the sub-quadrant's).
  void descend_y(Slot s, uint32_t y_top, int a, std::vector<uint32_t>& out) const {
    if (a == 0) return out.push_back(y_top);
    for (uint32_t b = 0; b < 2; ++b) {
      const uint32_t y = (y_top << 1) | b;
      if (!occ_.occupied(a - 1, s.x >> (f_ - (a - 1)), y)) descend_y(s, y, a - 1, out);
    }
  }
  const IntervalOccupancy& occ_;
  int m_, f_;
};

// The sub-quadrants the new points of a doubling from `count` points fill, one point each.
// Even step (count = 4^k, cells of side 2^-k hold one point each): the sub-quadrant
// diagonally opposite each point in its cell, the only one leaving its 2^-(k+1) x 2^-k and
// 2^-k x 2^-(k+1) intervals free. Odd step (count = 2 * 4^k: cells hold two points in
// diagonal sub-quadrants): the two other sub-quadrants of each cell.
std::vector<Slot> open_slots(const Pmj02Points& p, int f) {
  const uint32_t count = uint32_t(p.size());
  const bool even = std::countr_zero(count) % 2 == 0;
  std::vector<Slot> slots;
  for (uint32_t i = 0; i < (even ? count : count / 2); ++i) {
    const uint32_t x = top_bits(p[i][0], f), y = top_bits(p[i][1], f);
    if (even) {
      slots.push_back({x ^ 1u, y ^ 1u});
    } else {
      slots.push_back({x ^ 1u, y});
      slots.push_back({x, y ^ 1u});
    }
  }
  return slots;
}

// Doubles the sequence. Each new point is the best of `candidates` trials, each a random open
// sub-quadrant and a uniformly random position among its valid ones; plain pmj02
// (candidates = 1) takes the sub-quadrants in a random order. Once a sub-quadrant has
// no valid position it never will (occupancy only grows), so the construction would be stuck:
// that is checked and never happens for the sets made here (tests/samplers).
void extend(Pmj02Points& p, int candidates, Pcg32& rng) {
  const uint32_t count = uint32_t(p.size());
  const int m = std::countr_zero(count) + 1;  // the doubled prefix is a (0,m,2)-net
  IntervalOccupancy occ(m);
  PointGrid grid(m);
  for (uint32_t i = 0; i < count; ++i) occ.add(p[i]), grid.add(int32_t(i), p[i]);
  const StrataSearch search(occ, m);
  std::vector<Slot> slots = open_slots(p, (m + 1) / 2);
  for (uint32_t j = count; j < 2 * count; ++j) {
    std::array<uint32_t, 2> best{};
    double best_d2 = -1;
    size_t best_slot = 0;
    for (int c = 0; c < candidates; ++c) {
      const size_t k = rng.next_u32() % slots.size();
      const ValidStrata v = search(slots[k]);
      if (v.empty()) throw std::logic_error("pmj02 construction: a sub-quadrant has no valid position");
      const uint32_t x = v.x[rng.next_u32() % v.x.size()], y = v.y[rng.next_u32() % v.y.size()];
      const std::array<uint32_t, 2> q{(x << (32 - m)) | (rng.next_u32() >> m), (y << (32 - m)) | (rng.next_u32() >> m)};
      const double d2 = candidates == 1 ? 0.0 : grid.min_distance2(p, q, best_d2);
      if (d2 > best_d2) best_d2 = d2, best = q, best_slot = k;
    }
    slots[best_slot] = slots.back();
    slots.pop_back();
    p.push_back(best);
    occ.add(best);
    grid.add(int32_t(j), best);
  }
}

}  // namespace

Pmj02Points make_pmj02_points(uint32_t n, uint64_t seed, int candidates) {
  Pcg32 rng(seed, mix_bits(seed));
  Pmj02Points p;
  p.reserve(n);
  p.push_back({rng.next_u32(), rng.next_u32()});
  while (p.size() < n) extend(p, candidates, rng);
  return p;
}

}  // namespace eyetrace
