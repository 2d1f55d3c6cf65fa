// Running eyetrace under Open MPI's mpirun in tests (tests/distributed): root may run it only when
// told to (the CI machine runs as root), and --oversubscribe allows more ranks than cores.
#pragma once
#include <cstdlib>
#include <string>
#include <vector>

#include "eyetrace_process.h"

namespace eyetrace::test {

inline void allow_mpirun_as_root() {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
}

// mpirun -n RANKS eyetrace ARGS, output to `log`, without waiting; the pid or -1.
inline pid_t spawn_mpirun(int ranks, const std::vector<std::string>& args, const std::string& log) {
  allow_mpirun_as_root();
  std::vector<std::string> words = {"--oversubscribe", "-n", std::to_string(ranks), eyetrace_binary()};
  words.insert(words.end(), args.begin(), args.end());
  return spawn_logged("mpirun", words, log);
}

// The same, waited for: the exit status as wait_exit gives it, or -1.
inline int run_mpirun(int ranks, const std::vector<std::string>& args, const std::string& log) {
  const pid_t pid = spawn_mpirun(ranks, args, log);
  return pid > 0 ? wait_exit(pid) : -1;
}

}  // namespace eyetrace::test
