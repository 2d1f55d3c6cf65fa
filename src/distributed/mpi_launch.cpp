// join_render_group() of a build with MPI.
#include <cstdlib>

#include "distributed/launch.h"
#include "distributed/mpi_render_group.h"

namespace eyetrace {

std::unique_ptr<RenderGroup> join_render_group() {
  // Started by a launcher (Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE, MPICH's PMI_SIZE): join
  // its world. Otherwise a group of one, without initialising MPI at all, so a plain run costs
  // nothing and needs no MPI runtime configuration.
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (std::getenv(var)) return std::make_unique<MpiRenderGroup>();
  return std::make_unique<RenderGroup>();
}

bool built_with_mpi() { return true; }

}  // namespace eyetrace
