#include "distributed/mpi_render_group.h"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <stdexcept>

#include "render/film.h"
#include "render/tile_progress.h"

namespace eyetrace {

namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// The values one tile contributes to share(): its count, then per pixel (row-major) the film's
// accumulators and, adaptive, the pixel's count and target. Counts are small integers, exact
// in a double.
void pack_tile(size_t t, const std::vector<double>& acc, size_t per, const TileProgress& tp, const PixelBounds& b,
               std::vector<double>& out) {
  out.push_back(tp.done[t]);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      out.insert(out.end(), acc.begin() + std::ptrdiff_t(i * per), acc.begin() + std::ptrdiff_t((i + 1) * per));
      if (tp.adaptive()) out.insert(out.end(), {double(tp.pixel_done[i]), double(tp.pixel_target[i])});
    }
}

const double* unpack_tile(size_t t, const double* in, std::vector<double>& acc, size_t per, TileProgress& tp,
                          const PixelBounds& b) {
  tp.done[t] = int(*in++);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      std::copy(in, in + per, acc.begin() + std::ptrdiff_t(i * per));
      in += per;
      if (tp.adaptive()) {
        tp.pixel_done[i] = int(in[0]);
        tp.pixel_target[i] = int(in[1]);
        in += 2;
      }
    }
  return in;
}

}  // namespace

MpiRenderGroup::MpiRenderGroup() {
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiRenderGroup::~MpiRenderGroup() { MPI_Finalize(); }

void MpiRenderGroup::abort_job() {
  if (size_ == 1) return;
  std::fprintf(stderr, "eyetrace: rank %d of %d stops the job after an error\n", rank_, size_);
  MPI_Abort(MPI_COMM_WORLD, 1);
}

bool MpiRenderGroup::any(bool v) {
  int in = v ? 1 : 0, out = 0;
  check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
  return out != 0;
}

int MpiRenderGroup::min(int v) {
  int out = 0;
  check(MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

double MpiRenderGroup::max(double v) {
  double out = 0;
  check(MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

uint64_t MpiRenderGroup::sum(uint64_t v) {
  uint64_t out = 0;
  check(MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

uint64_t MpiRenderGroup::broadcast(uint64_t v) {
  check(MPI_Bcast(&v, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return v;
}

std::vector<double> MpiRenderGroup::gather(double v) {
  std::vector<double> all(rank_ == 0 ? size_t(size_) : 0);
  check(MPI_Gather(&v, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD), "MPI_Gather");
  return all;
}

void MpiRenderGroup::share(Film& film, TileProgress& tp) {
  const PixelBounds& b = film.bounds();
  const size_t per = film.accumulators_per_pixel();
  std::vector<double> acc = film.accumulators();
  std::vector<double> mine;
  const size_t tiles = tp.done.size();
  for (size_t t = 0; t < tiles; ++t)
    if (owns_tile(t, tiles)) pack_tile(t, acc, per, tp, b, mine);
  // Every rank's part, in rank order (MPI counts are ints: a film beyond 2^31 doubles per rank
  // would need chunking; that is 16 GiB of accumulators).
  if (mine.size() > size_t(INT32_MAX)) throw std::runtime_error("MPI: a rank's share of the film is too large");
  int count = int(mine.size());
  const size_t ranks = static_cast<size_t>(size_);
  std::vector<int> counts(ranks), offsets(ranks);
  check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  size_t total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[size_t(r)] = int(total);
    total += size_t(counts[size_t(r)]);
  }
  if (total > size_t(INT32_MAX)) throw std::runtime_error("MPI: the film is too large to share");
  std::vector<double> all(total);
  check(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  for (int r = 0; r < size_; ++r) {
    const double* in = all.data() + offsets[size_t(r)];
    for (size_t t = 0; t < tiles; ++t)
      if (tile_owner(t, tiles) == r) in = unpack_tile(t, in, acc, per, tp, b);
  }
  film.restore(acc, film.nonfinite_samples());
}

}  // namespace eyetrace
