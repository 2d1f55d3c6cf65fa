// join_render_group() of a build with MPI.
#include "distributed/launch.h"
#include "distributed/mpi_render_group.h"

namespace eyetrace {

std::unique_ptr<RenderGroup> join_render_group() {
  if (launched_processes() > 0) return std::make_unique<MpiRenderGroup>();
  return std::make_unique<RenderGroup>();
}

}  // namespace eyetrace
