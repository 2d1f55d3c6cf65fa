// A RenderGroup over MPI_COMM_WORLD (render/render_group.h): the collectives are MPI
// all-reductions, and share() an all-gather of each rank's own tiles; collect() is share() to
// rank 0 alone: what checkpoints need; collect_image() gathers a finished render's image values.
#pragma once
#include <vector>

#include "distributed/mpi_session.h"
#include "render/render_group.h"

namespace eyetrace {

class MpiRenderGroup : public RenderGroup {
 public:
  int rank() const override { return session_.rank(); }
  int size() const override { return session_.size(); }
  bool any(bool v) override;
  int min(int v) override;
  double max(double v) override;
  uint64_t sum(uint64_t v) override;
  uint64_t broadcast(uint64_t v) override;
  std::vector<double> gather(double v) override;
  void share(Film& film, TileProgress& tiles) override;
  void collect(Film& film, TileProgress& tiles) override;
  Image collect_image(const Film& film, TileProgress& tiles) override;
  void abort_job() override { session_.abort_job("render"); }

 private:
  std::vector<double> own_tiles(const Film& film, const TileProgress& tp) const;
  // Every other rank's tiles from `all` (rank r's part at offsets[r]) into the film.
  void unpack_others(const std::vector<double>& all, const std::vector<int>& offsets, Film& film,
                     TileProgress& tp) const;
  MpiSession session_;
};

}  // namespace eyetrace
