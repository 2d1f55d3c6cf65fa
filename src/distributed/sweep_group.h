// The processes of a parameter sweep under `mpirun` (docs/sweeps.md, docs/cluster.md): rank 0
// hands out the sweep's jobs one at a time, each other rank runs one, reports its result and asks
// for the next (dynamic load balancing: a rank that finishes early takes more). Alone (no mpirun,
// or a build without MPI) the group has one process and the sweep runs its jobs locally.
// Implementations: mpi_sweep_group.cpp (with MPI), single_launch.cpp (without).
#pragma once
#include <memory>
#include <string>

namespace eyetrace {

class SweepGroup {
 public:
  virtual ~SweepGroup() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }

  // A worker's request as rank 0 receives it: who asks, and the result of its last job ("" for
  // none yet), as the worker wrote it.
  struct Request {
    int worker = 0;
    std::string result;
  };
  // Rank 0: waits for the next request from any worker.
  virtual Request receive() { return {}; }
  // Rank 0: answers `worker` with a job index, or -1: no more jobs, stop.
  virtual void answer(int /*worker*/, int /*job*/) {}
  // A worker: sends its last result ("" for none) and waits for the next job index (-1: stop).
  virtual int ask(const std::string& /*result*/) { return -1; }
  // After an error on one rank that the others could wait for: ends the whole job.
  virtual void abort_job() {}
};

// The sweep group this process belongs to (MPI's world under mpirun, else a group of one).
std::unique_ptr<SweepGroup> join_sweep_group();

}  // namespace eyetrace
