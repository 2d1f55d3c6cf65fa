// A SweepGroup over MPI_COMM_WORLD: requests and answers are point-to-point messages (a worker's
// result as text; an answer as one int), so rank 0 serves whichever worker asks first.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "distributed/sweep_group.h"

namespace eyetrace {

namespace {

constexpr int kRequestTag = 1, kAnswerTag = 2;

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

class MpiSweepGroup : public SweepGroup {
 public:
  MpiSweepGroup() {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSweepGroup() override { MPI_Finalize(); }
  MpiSweepGroup(const MpiSweepGroup&) = delete;
  MpiSweepGroup& operator=(const MpiSweepGroup&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  Request receive() override {
    MPI_Status status;
    check(MPI_Probe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &status), "MPI_Probe");
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::vector<char> text(size_t(length) + 1, '\0');
    check(MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    return {status.MPI_SOURCE, std::string(text.data(), size_t(length))};
  }

  void answer(int worker, int job) override {
    check(MPI_Send(&job, 1, MPI_INT, worker, kAnswerTag, MPI_COMM_WORLD), "MPI_Send");
  }

  int ask(const std::string& result) override {
    check(MPI_Send(result.data(), int(result.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD), "MPI_Send");
    int job = -1;
    check(MPI_Recv(&job, 1, MPI_INT, 0, kAnswerTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    return job;
  }

  void abort_job() override {
    if (size_ == 1) return;
    std::fprintf(stderr, "eyetrace: sweep rank %d of %d stops the job after an error\n", rank_, size_);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<SweepGroup> join_sweep_group() {
  // As join_render_group (mpi_launch.cpp): MPI only when a launcher started this process.
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (std::getenv(var)) return std::make_unique<MpiSweepGroup>();
  return std::make_unique<SweepGroup>();
}

}  // namespace eyetrace
