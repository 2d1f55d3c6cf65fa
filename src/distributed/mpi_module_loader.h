// Finds and loads the MPI module (distributed/mpi_module.h), once, when a process started by a
// launcher joins its render or sweep group (distributed/mpi_launch.cpp): where
// core/module_loader.h looks, the environment variable being EYETRACE_MPI_MODULE_DIR. A plain
// run never calls this and maps no MPI library.
#pragma once
#include "distributed/mpi_module.h"

namespace eyetrace {

// The module's factories. Throws SceneError naming `what` (the command that needs MPI) and
// every place tried, with dlopen's reason, when it cannot be loaded.
const MpiModule& mpi_module(const char* what);

// The module's file name (libeyetrace_mpi.so).
extern const char* const kMpiModuleName;

}  // namespace eyetrace
