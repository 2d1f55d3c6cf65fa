// The processes that render one image together: MPI ranks under `mpirun`
// (src/distributed/mpi_render_group.h), or one process alone, which this base class is.
//
// Work is split by tiles (owns_tile), and the rank that owns a tile takes all of the
// tile's samples, in the same order as a single process would, so every pixel's sums are the same
// bits whatever the number of ranks and threads. The render loop calls the collectives below at
// the same points on every rank (once per pass), which keeps pass sizes, stopping and adaptive
// decisions identical everywhere; share() makes every rank's film whole (each rank's own tiles go
// to all) before an adaptive decision, collect() makes rank 0's whole before a checkpoint and the
// final image.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace eyetrace {

class Film;
struct Image;
struct TileProgress;

class RenderGroup {
 public:
  virtual ~RenderGroup() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }

  // How tiles are dealt out: interleaved (tile t to rank t mod N, the default: costly and cheap
  // regions of the image spread over all ranks) or in N contiguous blocks of rows (kept to
  // measure the difference: docs/cluster.md).
  enum class Split { kInterleaved, kBlocks };
  void set_split(Split s) { split_ = s; }
  // The rank that renders tile t of `count`.
  int tile_owner(size_t t, size_t count) const {
    const size_t n = size_t(size());
    return int(split_ == Split::kInterleaved ? t % n : t * n / count);
  }
  bool owns_tile(size_t t, size_t count) const { return tile_owner(t, count) == rank(); }

  // Collectives: every rank calls each of them, in the same order.
  virtual bool any(bool v) { return v; }
  virtual int min(int v) { return v; }
  virtual double max(double v) { return v; }
  virtual uint64_t sum(uint64_t v) { return v; }
  // Rank 0's value, on every rank.
  virtual uint64_t broadcast(uint64_t v) { return v; }
  // Rank 0 receives every rank's value, in rank order (the other ranks: an empty vector).
  virtual std::vector<double> gather(double v) { return {v}; }
  // Every rank's film accumulators and tile (and, adaptive, pixel) counts for the tiles it owns
  // go to every rank. A rank's count of non-finite samples stays its own.
  virtual void share(Film&, TileProgress&) {}
  // The same to rank 0 alone (its film and progress become whole; the others' stay their own):
  // what a checkpoint or an interrupted render's resumable state needs, which rank 0 writes.
  virtual void collect(Film&, TileProgress&) {}
  // A finished render's image on rank 0 (the others: an empty image), with rank 0's progress
  // made whole, gathering what the image needs and no more: every other rank's tiles' image
  // values (Film::pixel_channels, 3 + buckets floats a pixel instead of the film's 8 + 2 x
  // buckets doubles) and tile counts. The values are the bits one process computes from the
  // same sums. Alone: the film's image.
  virtual Image collect_image(const Film& film, TileProgress&);
  // Whether every pixel of every rank has all the samples it will get (TileProgress::complete
  // over the whole job; a rank knows only its own tiles' counts until collect).
  bool complete(const TileProgress& tp, int spp);
  // After an error on this rank while the others may wait for it in a collective: ends the
  // whole job (MPI_Abort). Nothing to do alone.
  virtual void abort_job() {}

 private:
  Split split_ = Split::kInterleaved;
};

}  // namespace eyetrace
