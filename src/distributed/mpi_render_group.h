// A RenderGroup over MPI_COMM_WORLD (render/render_group.h): the collectives are MPI
// all-reductions, and share() an all-gather of each rank's own tiles. MPI is initialised with
// MPI_THREAD_FUNNELED: only the thread that runs the render loop calls MPI, never TBB's workers.
// collect() is share() to rank 0 alone: what the final image and checkpoints need.
#pragma once
#include <vector>

#include "render/render_group.h"

namespace eyetrace {

class MpiRenderGroup : public RenderGroup {
 public:
  MpiRenderGroup();            // MPI_Init_thread
  ~MpiRenderGroup() override;  // MPI_Finalize
  MpiRenderGroup(const MpiRenderGroup&) = delete;
  MpiRenderGroup& operator=(const MpiRenderGroup&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  bool any(bool v) override;
  int min(int v) override;
  double max(double v) override;
  uint64_t sum(uint64_t v) override;
  uint64_t broadcast(uint64_t v) override;
  std::vector<double> gather(double v) override;
  void share(Film& film, TileProgress& tiles) override;
  void collect(Film& film, TileProgress& tiles) override;
  void abort_job() override;

 private:
  std::vector<double> own_tiles(const Film& film, const TileProgress& tp) const;
  // Every other rank's tiles from `all` (rank r's part at offsets[r]) into the film.
  void unpack_others(const std::vector<double>& all, const std::vector<int>& offsets, Film& film,
                     TileProgress& tp) const;
  int rank_ = 0, size_ = 1;
};

}  // namespace eyetrace
