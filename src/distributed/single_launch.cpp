// join_render_group() of a build without MPI.
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "distributed/launch.h"

namespace eyetrace {

std::unique_ptr<RenderGroup> join_render_group() {
  // Open MPI's and MPICH's launchers tell each process how many there are.
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(var); n && std::atoi(n) > 1)
      throw_error(fmt::format(
          "this eyetrace was built without MPI, but it was started as one of {} processes ({}): each would render "
          "and write the whole image. Rebuild with MPI (libopenmpi-dev installed; CMake finds it) or run one process",
          n, var));
  return std::make_unique<RenderGroup>();
}

bool built_with_mpi() { return false; }

}  // namespace eyetrace
