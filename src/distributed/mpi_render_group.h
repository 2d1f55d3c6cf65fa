// A RenderGroup over MPI_COMM_WORLD (render/render_group.h): the collectives are MPI
// all-reductions, and share() an all-gather of each rank's own tiles. MPI is initialised with
// MPI_THREAD_FUNNELED: only the thread that runs the render loop calls MPI, never TBB's workers.
#pragma once
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
  void abort_job() override;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace eyetrace
