// join_render_group() and join_sweep_group() of a build without MPI.
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "distributed/launch.h"
#include "distributed/sweep_group.h"

namespace eyetrace {

namespace {

void refuse_several_ranks(const char* what) {
  if (const int n = launched_processes(); n > 1)
    throw_error(
        fmt::format("this eyetrace was built without MPI, but it was started as one of {} processes: each would {}. "
                    "Rebuild with MPI (libopenmpi-dev installed; CMake finds it) or run one process",
                    n, what));
}

}  // namespace

std::unique_ptr<RenderGroup> join_render_group() {
  refuse_several_ranks("render and write the whole image");
  return std::make_unique<RenderGroup>();
}

std::unique_ptr<SweepGroup> join_sweep_group() {
  refuse_several_ranks("run every job of the sweep");
  return std::make_unique<SweepGroup>();
}

}  // namespace eyetrace
