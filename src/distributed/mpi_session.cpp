#include "distributed/mpi_session.h"

#include <mpi.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace eyetrace {

void mpi_check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

MpiSession::MpiSession() {
  int provided = 0;
  mpi_check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::abort_job(const char* what) const {
  if (size_ == 1) return;
  std::fprintf(stderr, "eyetrace: %s rank %d of %d stops the job after an error\n", what, rank_, size_);
  MPI_Abort(MPI_COMM_WORLD, 1);
}

}  // namespace eyetrace
