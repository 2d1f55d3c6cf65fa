// How `eyetrace render` (and `sweep`, distributed/sweep_group.h) learns whether it is one of several
// processes started by `mpirun`.
// Two implementations, one per build: mpi_launch.cpp (built when CMake finds MPI) joins
// MPI_COMM_WORLD through the MPI module it then loads (distributed/mpi_module.h);
// single_launch.cpp (built without MPI) refuses to run as one of several ranks, which would
// otherwise each render and write the whole image.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <memory>

#include "render/render_group.h"

namespace eyetrace {

// The group this process renders in: MPI's world under mpirun, else a group of one. The
// returned object owns the MPI session (initialised here, finalised when it is destroyed).
// Throws SceneError when MPI is needed and its module cannot be loaded.
std::unique_ptr<RenderGroup> join_render_group();

// How many processes an MPI launcher started this job with (Open MPI's mpirun sets
// OMPI_COMM_WORLD_SIZE, MPICH's and Slurm's PMI set PMI_SIZE); 0 when no launcher started this
// process. Both builds ask it: an MPI build loads its MPI module and initialises MPI only then (a
// plain run maps no MPI library and needs no MPI runtime), a build without MPI refuses to be one
// of several.
inline int launched_processes() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(var)) return std::max(1, std::atoi(n));
  return 0;
}

}  // namespace eyetrace
