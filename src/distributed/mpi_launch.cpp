// join_render_group() and join_sweep_group() of a build with MPI: under a launcher, the MPI
// module (distributed/mpi_module.h) is loaded and MPI initialised; alone, neither.
#include "distributed/launch.h"
#include "distributed/mpi_module_loader.h"
#include "distributed/mpi_render_group.h"
#include "distributed/sweep_group.h"

namespace eyetrace {

std::unique_ptr<RenderGroup> join_render_group() {
  if (launched_processes() > 0)
    return std::make_unique<MpiRenderGroup>(std::unique_ptr<MpiWorld>(mpi_module("render").join_world()));
  return std::make_unique<RenderGroup>();
}

std::unique_ptr<SweepGroup> join_sweep_group() {
  if (launched_processes() > 0) return std::unique_ptr<SweepGroup>(mpi_module("sweep").join_sweep_group());
  return std::make_unique<SweepGroup>();
}

}  // namespace eyetrace
