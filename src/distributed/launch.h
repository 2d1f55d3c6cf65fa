// How `eyetrace render` learns whether it is one of several processes started by `mpirun`.
// Two implementations, one per build: mpi_launch.cpp (built when CMake finds MPI) joins
// MPI_COMM_WORLD; single_launch.cpp (built without MPI) refuses to run as one of several ranks,
// which would otherwise each render and write the whole image.
#pragma once
#include <memory>

#include "render/render_group.h"

namespace eyetrace {

// The group this process renders in: MPI's world under mpirun, else a group of one. The
// returned object owns the MPI session (initialised here, finalised when it is destroyed).
std::unique_ptr<RenderGroup> join_render_group();

// Whether this binary was built with MPI (for `eyetrace --version` style reports and tests).
bool built_with_mpi();

}  // namespace eyetrace
