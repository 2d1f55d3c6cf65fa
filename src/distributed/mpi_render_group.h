// A RenderGroup over MPI_COMM_WORLD (render/render_group.h), built on the MPI module's
// collectives (distributed/mpi_module.h): the one-number collectives are its all-reductions,
// share() an all-gather of each rank's own tiles; collect() is share() to rank 0 alone: what
// checkpoints need; collect_image() gathers a finished render's image values. Cutting the film
// into tiles is done here, in the program, so the module needs nothing of eyetrace.
#pragma once
#include <memory>
#include <vector>

#include "distributed/mpi_module.h"
#include "render/render_group.h"

namespace eyetrace {

class MpiRenderGroup : public RenderGroup {
 public:
  explicit MpiRenderGroup(std::unique_ptr<MpiWorld> world) : world_(std::move(world)) {}
  int rank() const override { return world_->rank(); }
  int size() const override { return world_->size(); }
  bool any(bool v) override { return world_->any(v); }
  int min(int v) override { return world_->min(v); }
  double max(double v) override { return world_->max(v); }
  uint64_t sum(uint64_t v) override { return world_->sum(v); }
  uint64_t broadcast(uint64_t v) override { return world_->broadcast(v); }
  std::vector<double> gather(double v) override { return world_->gather(v); }
  void share(Film& film, TileProgress& tiles) override;
  void collect(Film& film, TileProgress& tiles) override;
  Image collect_image(const Film& film, TileProgress& tiles) override;
  void abort_job() override { world_->abort_job("render"); }

 private:
  std::vector<double> own_tiles(const Film& film, const TileProgress& tp) const;
  // Every other rank's tiles from `all` (rank r's part at offsets[r]) into the film.
  void unpack_others(const std::vector<double>& all, const std::vector<int>& offsets, Film& film,
                     TileProgress& tp) const;
  std::unique_ptr<MpiWorld> world_;
};

}  // namespace eyetrace
