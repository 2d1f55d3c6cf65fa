// The MPI session of one eyetrace process under mpirun (MPI builds only): initialised with
// MPI_THREAD_FUNNELED (only the thread that runs the command calls MPI, never TBB's workers),
// finalised when destroyed. The render and sweep groups each hold one.
#pragma once

namespace eyetrace {

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

}  // namespace eyetrace
