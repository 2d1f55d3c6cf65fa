// The MPI session of one eyetrace process under mpirun, in the MPI module (distributed/mpi_module.h):
// initialised with MPI_THREAD_FUNNELED (only the thread that runs the command calls MPI, never
// TBB's workers), finalised when destroyed. The module's world and sweep group each hold one.
#pragma once

namespace eyetrace {

class MpiWorld;
class SweepGroup;

class MpiSession {
 public:
  MpiSession();   // MPI_Init_thread
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // After an error on this rank that the others could wait for: says so and ends the whole job
  // (MPI_Abort). Nothing to do alone.
  void abort_job(const char* what) const;

 private:
  int rank_ = 0, size_ = 1;
};

// Throws std::runtime_error naming `what` unless `code` is MPI_SUCCESS.
void mpi_check(int code, const char* what);

// The module's factories (mpi_world.cpp, mpi_sweep_group.cpp), which its entry point gives out
// (mpi_module.cpp). Each makes a session: MPI_Init_thread.
MpiWorld* new_mpi_world();
SweepGroup* new_mpi_sweep_group();

}  // namespace eyetrace
