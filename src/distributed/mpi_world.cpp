// MpiWorld (distributed/mpi_module.h) over MPI_COMM_WORLD, in the MPI module: one-number
// collectives are all-reductions; vectors are gathered with a gather of the counts, then
// MPI_Gatherv or MPI_Allgatherv.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "distributed/mpi_module.h"
#include "distributed/mpi_session.h"

namespace eyetrace {

namespace {

// Displacements of per-rank blocks of `counts`; throws when the total does not fit MPI's ints.
std::vector<int> offsets_of(const std::vector<int>& counts) {
  std::vector<int> offsets(counts.size());
  size_t total = 0;
  for (size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = int(total);
    total += size_t(counts[r]);
  }
  // MPI counts are ints: a film beyond 2^31 doubles (16 GiB of accumulators) would need chunking.
  if (total > size_t(INT32_MAX)) throw std::runtime_error("MPI: the film is too large to gather in one message");
  return offsets;
}

// MPI's type for T.
template <class T>
MPI_Datatype mpi_type();
template <>
MPI_Datatype mpi_type<double>() {
  return MPI_DOUBLE;
}
template <>
MPI_Datatype mpi_type<float>() {
  return MPI_FLOAT;
}
template <>
MPI_Datatype mpi_type<int>() {
  return MPI_INT;
}

template <class T>
void gather_to_root_of(const std::vector<T>& mine, int rank, int size, std::vector<T>& all, std::vector<int>& offsets) {
  if (mine.size() > size_t(INT32_MAX)) throw std::runtime_error("MPI: a rank's share of the film is too large");
  const int count = int(mine.size());
  std::vector<int> counts(rank == 0 ? static_cast<size_t>(size) : 0);
  mpi_check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  if (rank == 0) {
    offsets = offsets_of(counts);
    all.resize(size_t(offsets.back()) + size_t(counts.back()));
  }
  mpi_check(MPI_Gatherv(mine.data(), count, mpi_type<T>(), all.data(), counts.data(), offsets.data(), mpi_type<T>(), 0,
                        MPI_COMM_WORLD),
            "MPI_Gatherv");
}

class MpiCommWorld : public MpiWorld {
 public:
  int rank() const override { return session_.rank(); }
  int size() const override { return session_.size(); }

  bool any(bool v) override {
    int in = v ? 1 : 0, out = 0;
    mpi_check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
    return out != 0;
  }

  int min(int v) override {
    int out = 0;
    mpi_check(MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
  }

  double max(double v) override {
    double out = 0;
    mpi_check(MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
  }

  uint64_t sum(uint64_t v) override {
    uint64_t out = 0;
    mpi_check(MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
    return out;
  }

  uint64_t broadcast(uint64_t v) override {
    mpi_check(MPI_Bcast(&v, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
    return v;
  }

  std::vector<double> gather(double v) override {
    std::vector<double> all(rank() == 0 ? size_t(size()) : 0);
    mpi_check(MPI_Gather(&v, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD), "MPI_Gather");
    return all;
  }

  void all_gather(const std::vector<double>& mine, std::vector<double>& all, std::vector<int>& offsets) override {
    if (mine.size() > size_t(INT32_MAX)) throw std::runtime_error("MPI: a rank's share of the film is too large");
    const int count = int(mine.size());
    std::vector<int> counts(static_cast<size_t>(size()));
    mpi_check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
    offsets = offsets_of(counts);
    all.resize(size_t(offsets.back()) + size_t(counts.back()));
    mpi_check(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                             MPI_COMM_WORLD),
              "MPI_Allgatherv");
  }

  void gather_to_root(const std::vector<double>& mine, std::vector<double>& all, std::vector<int>& offsets) override {
    gather_to_root_of(mine, rank(), size(), all, offsets);
  }
  void gather_to_root(const std::vector<float>& mine, std::vector<float>& all, std::vector<int>& offsets) override {
    gather_to_root_of(mine, rank(), size(), all, offsets);
  }
  void gather_to_root(const std::vector<int>& mine, std::vector<int>& all, std::vector<int>& offsets) override {
    gather_to_root_of(mine, rank(), size(), all, offsets);
  }

  void abort_job(const char* what) override { session_.abort_job(what); }

 private:
  MpiSession session_;
};

}  // namespace

MpiWorld* new_mpi_world() { return new MpiCommWorld; }

}  // namespace eyetrace
