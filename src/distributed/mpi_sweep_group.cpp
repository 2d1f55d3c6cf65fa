// A SweepGroup over MPI_COMM_WORLD, in the MPI module (distributed/mpi_module.h): requests and
// answers are point-to-point messages (a worker's result as text; an answer as one int), so rank
// 0 serves whichever worker asks first.
#include <mpi.h>

#include <stdexcept>
#include <vector>

#include "distributed/mpi_session.h"
#include "distributed/sweep_group.h"

namespace eyetrace {

namespace {

constexpr int kRequestTag = 1, kAnswerTag = 2;

class MpiSweepGroup : public SweepGroup {
 public:
  int rank() const override { return session_.rank(); }
  int size() const override { return session_.size(); }

  Request receive() override {
    MPI_Status status;
    mpi_check(MPI_Probe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &status), "MPI_Probe");
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::vector<char> text(size_t(length) + 1, '\0');
    mpi_check(
        MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
    return {status.MPI_SOURCE, std::string(text.data(), size_t(length))};
  }

  void answer(int worker, int job) override {
    mpi_check(MPI_Send(&job, 1, MPI_INT, worker, kAnswerTag, MPI_COMM_WORLD), "MPI_Send");
  }

  int ask(const std::string& result) override {
    mpi_check(MPI_Send(result.data(), int(result.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD), "MPI_Send");
    int job = -1;
    mpi_check(MPI_Recv(&job, 1, MPI_INT, 0, kAnswerTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    return job;
  }

  void abort_job() override { session_.abort_job("sweep"); }

 private:
  MpiSession session_;
};

}  // namespace

SweepGroup* new_mpi_sweep_group() { return new MpiSweepGroup; }

}  // namespace eyetrace
