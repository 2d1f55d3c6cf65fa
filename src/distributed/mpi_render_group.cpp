#include "distributed/mpi_render_group.h"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <stdexcept>

#include "render/film.h"
#include "render/tile_progress.h"

namespace eyetrace {

namespace {

// The values one tile contributes to share() and collect(): its count, then per pixel
// (row-major) the film's accumulators and, adaptive, the pixel's count and target. Counts are
// small integers, exact in a double.
void pack_tile(size_t t, const Film& film, const TileProgress& tp, std::vector<double>& out) {
  const PixelBounds& b = film.bounds();
  const size_t per = film.accumulators_per_pixel();
  out.push_back(tp.done[t]);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      out.resize(out.size() + per);
      film.copy_accumulators(i, out.data() + out.size() - per);
      if (tp.adaptive()) out.insert(out.end(), {double(tp.pixel_done[i]), double(tp.pixel_target[i])});
    }
}

const double* unpack_tile(size_t t, const double* in, Film& film, TileProgress& tp) {
  const PixelBounds& b = film.bounds();
  const size_t per = film.accumulators_per_pixel();
  tp.done[t] = int(*in++);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      film.set_accumulators(i, in);
      in += per;
      if (tp.adaptive()) {
        tp.pixel_done[i] = int(in[0]);
        tp.pixel_target[i] = int(in[1]);
        in += 2;
      }
    }
  return in;
}

// Displacements of per-rank blocks of `counts`; throws when the total does not fit MPI's ints.
std::vector<int> offsets_of(const std::vector<int>& counts) {
  std::vector<int> offsets(counts.size());
  size_t total = 0;
  for (size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = int(total);
    total += size_t(counts[r]);
  }
  // MPI counts are ints: a film beyond 2^31 doubles (16 GiB of accumulators) would need chunking.
  if (total > size_t(INT32_MAX)) throw std::runtime_error("MPI: the film is too large to gather in one message");
  return offsets;
}

}  // namespace

bool MpiRenderGroup::any(bool v) {
  int in = v ? 1 : 0, out = 0;
  mpi_check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
  return out != 0;
}

int MpiRenderGroup::min(int v) {
  int out = 0;
  mpi_check(MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

double MpiRenderGroup::max(double v) {
  double out = 0;
  mpi_check(MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

uint64_t MpiRenderGroup::sum(uint64_t v) {
  uint64_t out = 0;
  mpi_check(MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return out;
}

uint64_t MpiRenderGroup::broadcast(uint64_t v) {
  mpi_check(MPI_Bcast(&v, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return v;
}

std::vector<double> MpiRenderGroup::gather(double v) {
  std::vector<double> all(rank() == 0 ? size_t(size()) : 0);
  mpi_check(MPI_Gather(&v, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD), "MPI_Gather");
  return all;
}

std::vector<double> MpiRenderGroup::own_tiles(const Film& film, const TileProgress& tp) const {
  std::vector<double> mine;
  const size_t tiles = tp.done.size(), per = film.accumulators_per_pixel() + (tp.adaptive() ? 2 : 0);
  size_t values = 0;
  for (size_t t = 0; t < tiles; ++t)
    if (owns_tile(t, tiles)) values += 1 + tp.tile_bounds(t, film.bounds()).area() * per;
  mine.reserve(values);
  for (size_t t = 0; t < tiles; ++t)
    if (owns_tile(t, tiles)) pack_tile(t, film, tp, mine);
  if (mine.size() > size_t(INT32_MAX)) throw std::runtime_error("MPI: a rank's share of the film is too large");
  return mine;
}

void MpiRenderGroup::unpack_others(const std::vector<double>& all, const std::vector<int>& offsets, Film& film,
                                   TileProgress& tp) const {
  const size_t tiles = tp.done.size();
  for (int r = 0; r < size(); ++r) {
    if (r == rank()) continue;  // its own tiles are already in place
    const double* in = all.data() + offsets[size_t(r)];
    for (size_t t = 0; t < tiles; ++t)
      if (tile_owner(t, tiles) == r) in = unpack_tile(t, in, film, tp);
  }
}

void MpiRenderGroup::share(Film& film, TileProgress& tp) {
  const std::vector<double> mine = own_tiles(film, tp);
  const int count = int(mine.size());
  std::vector<int> counts(static_cast<size_t>(size()));
  mpi_check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  const std::vector<int> offsets = offsets_of(counts);
  std::vector<double> all(size_t(offsets.back()) + size_t(counts.back()));
  mpi_check(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                           MPI_COMM_WORLD),
            "MPI_Allgatherv");
  unpack_others(all, offsets, film, tp);
}

void MpiRenderGroup::collect(Film& film, TileProgress& tp) {
  // Rank 0 sends nothing (its tiles are in place); the others send theirs to it alone.
  const std::vector<double> mine = rank() == 0 ? std::vector<double>() : own_tiles(film, tp);
  const int count = int(mine.size());
  std::vector<int> counts(rank() == 0 ? static_cast<size_t>(size()) : 0);
  mpi_check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  std::vector<int> offsets;
  std::vector<double> all;
  if (rank() == 0) {
    offsets = offsets_of(counts);
    all.resize(size_t(offsets.back()) + size_t(counts.back()));
  }
  mpi_check(MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
                        MPI_COMM_WORLD),
            "MPI_Gatherv");
  if (rank() == 0) unpack_others(all, offsets, film, tp);
}

}  // namespace eyetrace
