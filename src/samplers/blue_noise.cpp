#include "samplers/blue_noise.h"

#include <cmath>
#include <limits>

#include "samplers/rng.h"

namespace eyetrace {

namespace {

constexpr double kSigma = 1.5;  // Ulichney's choice for the energy filter
constexpr int kRadius = 5;      // the Gaussian beyond 5 pixels (3.3 sigma) is below 0.4 % of its peak

// The Gaussian energy of the pattern's ones at every pixel of a toroidal texture, with the
// smallest energy among zeros and the largest among ones kept per row, so that finding the
// largest void or tightest cluster after a change rescans only the rows the change touched.
class EnergyField {
 public:
  explicit EnergyField(int size)
      : n_(size),
        energy_(size_t(size) * size, 0.0),
        ones_(size_t(size) * size, 0),
        row_min_zero_(size),
        row_max_one_(size) {
    for (int dy = -kRadius; dy <= kRadius; ++dy)
      for (int dx = -kRadius; dx <= kRadius; ++dx)
        kernel_.push_back(std::exp(-(dx * dx + dy * dy) / (2 * kSigma * kSigma)));
    for (int y = 0; y < n_; ++y) rescan_row(y);
  }
  bool is_one(int p) const { return ones_[size_t(p)] != 0; }
  void set(int p, bool one) {
    ones_[size_t(p)] = one;
    const int px = p % n_, py = p / n_;
    const double sign = one ? 1.0 : -1.0;
    for (int dy = -kRadius, k = 0; dy <= kRadius; ++dy) {
      const int y = wrap(py + dy);
      for (int dx = -kRadius; dx <= kRadius; ++dx, ++k)
        energy_[size_t(y) * n_ + size_t(wrap(px + dx))] += sign * kernel_[size_t(k)];
    }
    for (int dy = -kRadius; dy <= kRadius; ++dy) rescan_row(wrap(py + dy));
  }
  int largest_void() const {
    return best_of_rows(row_min_zero_, [](double a, double b) { return a < b; });
  }
  int tightest_cluster() const {
    return best_of_rows(row_max_one_, [](double a, double b) { return a > b; });
  }

 private:
  struct RowBest {
    double energy;
    int pixel;
  };
  int wrap(int v) const { return ((v % n_) + n_) % n_; }
  void rescan_row(int y) {
    RowBest lo{std::numeric_limits<double>::infinity(), -1}, hi{-std::numeric_limits<double>::infinity(), -1};
    for (int x = 0; x < n_; ++x) {
      const int p = y * n_ + x;
      const double e = energy_[size_t(p)];
      if (ones_[size_t(p)]) {
        if (e > hi.energy) hi = {e, p};
      } else if (e < lo.energy) {
        lo = {e, p};
      }
    }
    row_min_zero_[size_t(y)] = lo;
    row_max_one_[size_t(y)] = hi;
  }
  template <typename Better>
  static int best_of_rows(const std::vector<RowBest>& rows, Better better) {
    RowBest best = rows[0];
    for (const RowBest& r : rows)
      if (r.pixel >= 0 && (best.pixel < 0 || better(r.energy, best.energy))) best = r;
    return best.pixel;
  }
  int n_;
  std::vector<double> kernel_, energy_;
  std::vector<uint8_t> ones_;
  std::vector<RowBest> row_min_zero_, row_max_one_;
};

}  // namespace

std::vector<uint16_t> make_void_and_cluster(int size, uint64_t seed) {
  const int n = size * size;
  Pcg32 rng(seed, mix_bits(seed));
  // Initial pattern: a tenth of the pixels at random, relaxed until moving the tightest
  // cluster's one to the largest void would put it back where it was.
  EnergyField field(size);
  int ones = 0;
  while (ones < n / 10) {
    const int p = int(rng.next_u32() % uint32_t(n));
    if (!field.is_one(p)) field.set(p, true), ++ones;
  }
  for (int iteration = 0; iteration < n; ++iteration) {
    const int cluster = field.tightest_cluster();
    field.set(cluster, false);
    const int void_pixel = field.largest_void();
    field.set(void_pixel, true);
    if (void_pixel == cluster) break;
  }
  std::vector<uint16_t> rank(size_t(n), 0);
  // Phase 1: the initial pattern's ones, ranked down by removing the tightest cluster.
  EnergyField shrinking = field;
  for (int r = ones - 1; r >= 0; --r) {
    const int p = shrinking.tightest_cluster();
    rank[size_t(p)] = uint16_t(r);
    shrinking.set(p, false);
  }
  // Phases 2 and 3: the rest, ranked up by filling the largest void. (Ulichney's phase 3
  // takes the tightest cluster of zeros; with energies that sum to a constant over ones and
  // zeros, that is the zero of least energy from the ones: the same choice.)
  for (int r = ones; r < n; ++r) {
    const int p = field.largest_void();
    rank[size_t(p)] = uint16_t(r);
    field.set(p, true);
  }
  return rank;
}

}  // namespace eyetrace
