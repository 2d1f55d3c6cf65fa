// Everything eyetrace asks of MPI, as the interface of a module of its own. Open MPI's libraries
// (libmpi, libopen-pal, libopen-rte, hwloc, libevent, udev) cost every process their loading and
// resident pages, yet MPI is initialised only under a launcher (launched_processes(),
// distributed/launch.h); so MPI lives in build/lib/libeyetrace_mpi.so, which the program opens
// only then (distributed/mpi_module_loader.h). The module is the MPI session, MPI_COMM_WORLD's
// collectives on plain buffers (MpiWorld, below) and the sweep's messages (a SweepGroup); the
// render group that cuts the film into tiles for them stays in the program
// (distributed/mpi_render_group.h), so the module links nothing of eyetrace.
//
// Both sides are one build (the module is refused unless its interface version is this header's):
// an MPI error arrives as std::runtime_error, a type of the C++ runtime both share.
#pragma once
#include <cstdint>
#include <vector>

#include "distributed/sweep_group.h"

namespace eyetrace {

// MPI_COMM_WORLD of this process: made with MPI_Init_thread (MPI_THREAD_FUNNELED: only the
// thread that runs the command calls MPI), MPI_Finalize when destroyed. Every rank calls each
// collective, in the same order.
class MpiWorld {
 public:
  virtual ~MpiWorld() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual bool any(bool v) = 0;
  virtual int min(int v) = 0;
  virtual double max(double v) = 0;
  virtual uint64_t sum(uint64_t v) = 0;
  // Rank 0's value, on every rank.
  virtual uint64_t broadcast(uint64_t v) = 0;
  // Rank 0 receives every rank's value, in rank order (the other ranks: an empty vector).
  virtual std::vector<double> gather(double v) = 0;
  // Every rank's `mine` to every rank: `all` holds rank r's values from offsets[r].
  virtual void all_gather(const std::vector<double>& mine, std::vector<double>& all, std::vector<int>& offsets) = 0;
  // Every rank's `mine` to rank 0, the same way (`all` and `offsets` stay empty on the others).
  virtual void gather_to_root(const std::vector<double>& mine, std::vector<double>& all, std::vector<int>& offsets) = 0;
  virtual void gather_to_root(const std::vector<float>& mine, std::vector<float>& all, std::vector<int>& offsets) = 0;
  virtual void gather_to_root(const std::vector<int>& mine, std::vector<int>& all, std::vector<int>& offsets) = 0;
  // After an error on this rank that the others could wait for: says so on stderr (`what` is
  // "render" or "sweep") and ends the whole job (MPI_Abort). Nothing to do alone.
  virtual void abort_job(const char* what) = 0;
};

// Bumped whenever MpiWorld, SweepGroup or MpiModule changes.
constexpr int kMpiModuleVersion = 1;

// What the module's entry point gives: its interface version and two factories, one of which a
// process calls, once (each initialises MPI).
struct MpiModule {
  int version;                        // kMpiModuleVersion of the module's build
  MpiWorld* (*join_world)();          // for a render (owned by the caller)
  SweepGroup* (*join_sweep_group)();  // for a sweep: rank 0 dispatches, the others ask (owned by the caller)
};

}  // namespace eyetrace

// The module's one exported symbol.
#define EYETRACE_MPI_MODULE_ENTRY "eyetrace_mpi_module"
extern "C" const eyetrace::MpiModule* eyetrace_mpi_module();
