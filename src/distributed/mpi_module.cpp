// The MPI module's entry point (distributed/mpi_module.h): its interface version and factories.
#include "distributed/mpi_module.h"
#include "distributed/mpi_session.h"

extern "C" __attribute__((visibility("default"))) const eyetrace::MpiModule* eyetrace_mpi_module() {
  static const eyetrace::MpiModule module{eyetrace::kMpiModuleVersion, &eyetrace::new_mpi_world,
                                          &eyetrace::new_mpi_sweep_group};
  return &module;
}
