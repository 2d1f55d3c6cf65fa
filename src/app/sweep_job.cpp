// One sweep job as a child `eyetrace render` process (sweep_job.h says why a process).
#include "app/sweep_job.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace eyetrace {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The render writes its statistics here; the sweep adds the key and renames it to job.stats.
std::string partial_stats(const SweepJob& job) { return job.stats + ".part"; }

std::string key_text(uint64_t key) { return fmt::format("{:016x}", key); }

// The first line that says "error", else the first line; "" for an empty log.
std::string first_error_line(const std::string& log) {
  std::ifstream f(log);
  std::string line, first;
  while (std::getline(f, line)) {
    if (line.empty()) continue;
    if (line.find("error") != std::string::npos) return line;
    if (first.empty()) first = line;
  }
  return first;
}

void write_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    f << text;
    if (!f) throw std::runtime_error(fmt::format("\"{}\": cannot write", tmp));
  }
  fs::rename(tmp, path);
}

// This process's environment without the variables an MPI launcher sets (OMPI_*, PMIX_*, PMI_*):
// a render started by a sweep rank is one process of its own, not a rank of the sweep's job.
// Made before fork: the child of a threaded process (MPI runs threads) may only exec.
std::vector<std::string> environment_for_render() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string v = *e;
    if (v.rfind("OMPI_", 0) == 0 || v.rfind("PMIX_", 0) == 0 || v.rfind("PMI_", 0) == 0) continue;
    env.push_back(v);
  }
  return env;
}

// In the child: argv and envp are made by the parent before fork (the child of a threaded
// process may not allocate).
[[noreturn]] void exec_render(char* const* argv, char* const* envp, const char* log, pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGTERM);  // the sweep killed outright: its renders stop too
  if (getppid() != parent) _exit(143);
  // The sweep's handlers are inherited until exec: a signal passed on before then must stop this
  // process, not be swallowed by a copy of the sweep's handler. The parent blocks the signals
  // around fork; a pending one is delivered here, with the default action.
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  execve("/proc/self/exe", argv, envp);
  const char* msg = "error: cannot run /proc/self/exe\n";
  ssize_t ignored = write(STDERR_FILENO, msg, std::strlen(msg));
  (void)ignored;
  _exit(127);
}

}  // namespace

const char* status_name(JobStatus s) {
  switch (s) {
    case JobStatus::Done: return "done";
    case JobStatus::Skipped: return "skipped";
    case JobStatus::Failed: return "failed";
    case JobStatus::Interrupted: return "interrupted";
    case JobStatus::NotRun: return "not run";
  }
  return "?";
}

bool already_done(const SweepJob& job, JobResult& result) {
  if (!fs::exists(job.output) || !fs::exists(job.stats)) return false;
  std::ifstream f(job.stats);
  const json stats = json::parse(f, nullptr, /*allow_exceptions=*/false);
  if (!stats.is_object() || stats.value("sweep_key", "") != key_text(job.key)) return false;
  result.status = JobStatus::Skipped;
  result.render_seconds = stats.value("render_seconds", 0.0);
  result.spp = stats.value("samples_per_pixel", 0);
  return true;
}

pid_t start_job(const Sweep& sweep, const SweepJob& job, int threads) {
  const std::vector<std::string> args = job.render_args(sweep.scene, partial_stats(job), threads);
  const std::vector<std::string> env = environment_for_render();
  std::vector<char*> argv{const_cast<char*>("eyetrace")}, envp;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(fmt::format("{}: cannot start a process: {}", job.name, std::strerror(errno)));
  if (pid == 0) exec_render(argv.data(), envp.data(), job.log.c_str(), parent);
  return pid;
}

JobResult finish_job(const SweepJob& job, int wait_status) {
  JobResult r;
  const int code = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
  if (code == 0) {
    std::ifstream f(partial_stats(job));
    json stats = json::parse(f, nullptr, false);
    if (stats.is_object()) {
      stats["sweep_key"] = key_text(job.key);
      write_atomically(job.stats, stats.dump(2) + "\n");
      std::error_code ec;
      fs::remove(partial_stats(job), ec);
      fs::remove(job.log, ec);
      r.status = JobStatus::Done;
      r.render_seconds = stats.value("render_seconds", 0.0);
      r.spp = stats.value("samples_per_pixel", 0);
      return r;
    }
    r.status = JobStatus::Failed;
    r.error = fmt::format("the render wrote no statistics \"{}\"", partial_stats(job));
    return r;
  }
  // Stopped by a signal the sweep passed on: while loading the scene the render does not catch
  // it (nothing to save yet), later it saves its image and state and exits with 128 + signal.
  const bool signalled =
      WIFSIGNALED(wait_status) && (WTERMSIG(wait_status) == SIGINT || WTERMSIG(wait_status) == SIGTERM);
  if (signalled || code == 128 + SIGINT || code == 128 + SIGTERM) {
    r.status = JobStatus::Interrupted;
    return r;
  }
  r.status = JobStatus::Failed;
  r.error = first_error_line(job.log);
  if (r.error.empty())
    r.error = WIFSIGNALED(wait_status) ? fmt::format("killed by signal {}", WTERMSIG(wait_status))
                                       : fmt::format("exit status {}", code);
  return r;
}

}  // namespace eyetrace
