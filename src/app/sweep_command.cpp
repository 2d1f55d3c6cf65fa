// `eyetrace sweep SWEEPFILE`: every job of a parameter sweep (app/sweep.h), run by up to --jobs
// local processes, the next job going to the first free slot; finished outputs are skipped; the
// table is written once at the end. Under mpirun (distributed/sweep_group.h) rank 0 hands the
// same jobs out to the other ranks, one at a time, as each finishes its last.
#include <fmt/core.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "app/commands.h"
#include "app/sweep.h"
#include "app/sweep_job.h"
#include "app/sweep_table.h"
#include "distributed/sweep_group.h"

namespace eyetrace {

namespace {

struct SweepArgs {
  std::string file;
  int jobs = 1;
  int threads = 0;  // per job; 0: the cores shared among the jobs
  bool quiet = false;
};

// The running children, for the signal handler (which may only use lock-free atomics and kill).
constexpr int kMaxSlots = 1024;
std::atomic<pid_t> g_children[kMaxSlots];
std::atomic<int> g_signal{0};
static_assert(std::atomic<pid_t>::is_always_lock_free);

// First SIGINT/SIGTERM: no new jobs, the running renders are told to stop (they write what they
// have and its state, as `render` does) and the table is written. Second: the renders are told
// again (they quit at once) and the sweep exits without a table.
void on_signal(int sig) {
  const bool second = g_signal.exchange(sig) != 0;
  for (auto& c : g_children)
    if (pid_t p = c.load(); p > 0) kill(p, sig);
  if (second) _exit(128 + sig);
}

class SignalForwarding {
 public:
  SignalForwarding() {
    g_signal = 0;
    for (auto& c : g_children) c = 0;
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, &previous_[0]);
    sigaction(SIGTERM, &sa, &previous_[1]);
  }
  ~SignalForwarding() {
    sigaction(SIGINT, &previous_[0], nullptr);
    sigaction(SIGTERM, &previous_[1], nullptr);
  }
  // Starts a job with the signals blocked, so that none arrives between fork and the pid's
  // record in `slot` (the child unblocks them before exec).
  pid_t start(int slot, const Sweep& sweep, const SweepJob& job, int threads) {
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigprocmask(SIG_BLOCK, &block, &old);
    pid_t pid = -1;
    try {
      pid = start_job(sweep, job, threads);
      g_children[slot] = pid;
    } catch (...) {
      sigprocmask(SIG_SETMASK, &old, nullptr);
      throw;
    }
    sigprocmask(SIG_SETMASK, &old, nullptr);
    return pid;
  }

 private:
  struct sigaction previous_[2];
};

struct Progress {
  bool on;
  size_t total, finished = 0;
  void job(const SweepJob& job, const JobResult& r) {
    ++finished;
    if (!on) return;
    std::string detail = r.status == JobStatus::Failed ? ": " + r.error
                         : r.status == JobStatus::Done ? fmt::format(", {:.2f} s", r.render_seconds)
                                                       : "";
    fmt::print(stderr, "[{}/{}] {}: {}{}\n", finished, total, job.name, status_name(r.status), detail);
  }
};

// The jobs not already done, in order; those that are get their results (skipped) now.
std::vector<size_t> pending_jobs(const Sweep& sweep, std::vector<JobResult>& results, Progress& progress) {
  std::vector<size_t> pending;
  for (size_t i = 0; i < sweep.jobs.size(); ++i)
    if (already_done(sweep.jobs[i], results[i]))
      progress.job(sweep.jobs[i], results[i]);
    else
      pending.push_back(i);
  return pending;
}

// Runs every job not already done, at most `slots` at a time; results in job order.
std::vector<JobResult> run_jobs(const Sweep& sweep, int slots, int threads, Progress& progress) {
  std::vector<JobResult> results(sweep.jobs.size());
  const std::vector<size_t> pending = pending_jobs(sweep, results, progress);
  SignalForwarding signals;
  std::vector<std::pair<pid_t, size_t>> running(size_t(slots), {0, 0});  // slot -> (pid, job)
  size_t next = 0, busy = 0;
  while (busy > 0 || (next < pending.size() && g_signal == 0)) {
    for (int s = 0; s < slots && next < pending.size() && g_signal == 0; ++s)
      if (running[size_t(s)].first == 0) {
        const size_t j = pending[next++];
        running[size_t(s)] = {signals.start(s, sweep, sweep.jobs[j], threads), j};
        ++busy;
      }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(fmt::format("waiting for a render: {}", std::strerror(errno)));
    }
    for (int s = 0; s < slots; ++s)
      if (running[size_t(s)].first == pid) {
        g_children[s] = 0;
        const size_t j = running[size_t(s)].second;
        running[size_t(s)] = {0, 0};
        --busy;
        results[j] = finish_job(sweep.jobs[j], status);
        progress.job(sweep.jobs[j], results[j]);
      }
  }
  return results;
}

// What a worker tells rank 0 with each request: "<stop> <job> <status> <seconds> <spp> <error>"
// (tab-separated; job -1: no result yet; stop 1: this worker stops after it, having been
// signalled itself).
std::string encode_request(bool stop, int job, const JobResult& r) {
  return fmt::format("{}\t{}\t{}\t{:.17g}\t{}\t{}", stop ? 1 : 0, job, int(r.status), r.render_seconds, r.spp, r.error);
}

struct DecodedRequest {
  bool stop = false;
  int job = -1;
  JobResult result;
};

DecodedRequest decode_request(const std::string& text) {
  DecodedRequest d;
  int stop = 0, status = 0;
  size_t used = 0;
  if (std::sscanf(text.c_str(), "%d\t%d\t%d\t%lf\t%d\t%zn", &stop, &d.job, &status, &d.result.render_seconds,
                  &d.result.spp, &used) < 5)
    throw std::runtime_error("a sweep rank sent a malformed result");
  d.stop = stop != 0;
  d.result.status = JobStatus(status);
  d.result.error = text.substr(used);
  return d;
}

// Rank 0 of a sweep under mpirun: hands out the jobs not already done, one per request, to
// whichever worker asks, and gathers their results; once signalled it hands out no more.
std::vector<JobResult> dispatch(const Sweep& sweep, SweepGroup& group, Progress& progress) {
  std::vector<JobResult> results(sweep.jobs.size());
  const std::vector<size_t> pending = pending_jobs(sweep, results, progress);
  SignalForwarding signals;  // no children here: a signal only stops the handing out
  size_t next = 0;
  for (int working = group.size() - 1; working > 0;) {
    const SweepGroup::Request request = group.receive();
    const DecodedRequest d = decode_request(request.result);
    if (d.job >= 0 && size_t(d.job) < results.size()) {
      results[size_t(d.job)] = d.result;
      progress.job(sweep.jobs[size_t(d.job)], d.result);
    }
    if (!d.stop && g_signal == 0 && next < pending.size()) {
      group.answer(request.worker, int(pending[next++]));
    } else {
      group.answer(request.worker, -1);
      --working;
    }
  }
  return results;
}

// A worker rank: runs the job rank 0 hands it, in its own process as locally, until told to stop.
int work(const Sweep& sweep, SweepGroup& group, int threads) {
  SignalForwarding signals;  // mpirun passes a Ctrl-C on to every rank; this one to its render
  int job = group.ask(encode_request(false, -1, {}));
  while (job >= 0) {
    const pid_t pid = signals.start(0, sweep, sweep.jobs[size_t(job)], threads);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    g_children[0] = 0;
    const JobResult r = finish_job(sweep.jobs[size_t(job)], status);
    job = group.ask(encode_request(g_signal != 0, job, r));
  }
  return g_signal != 0 ? 128 + g_signal : 0;
}

int run_sweep_over_ranks(const SweepArgs& a, SweepGroup& group) {
  Sweep sweep;
  try {
    if (a.jobs > 1)
      throw std::runtime_error("under mpirun each rank runs one render at a time: give more ranks, not --jobs");
    sweep = read_sweep(a.file);  // every input error before the first render, on every rank
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", group.rank() > 0 ? fmt::format("rank {}: ", group.rank()).c_str() : "",
                 e.what());
    group.abort_job();  // the other ranks may already wait for this one
    return 1;
  }
  const int threads = a.threads > 0 ? a.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  if (group.rank() > 0) return work(sweep, group, threads);
  Progress progress{!a.quiet && isatty(STDERR_FILENO) != 0, sweep.jobs.size()};
  if (progress.on)
    fmt::print(stderr, "sweep {}: {} jobs over {} ranks ({} render, {} threads each)\n", a.file, sweep.jobs.size(),
               group.size(), group.size() - 1, threads);
  const std::vector<JobResult> results = dispatch(sweep, group, progress);
  write_sweep_table(sweep, results);
  size_t failed = 0;
  for (const JobResult& r : results) failed += r.status == JobStatus::Failed;
  if (g_signal != 0) return 128 + g_signal;
  return failed ? 1 : 0;
}

int run_sweep(const SweepArgs& a) {
  std::unique_ptr<SweepGroup> group = join_sweep_group();
  if (group->size() > 1) return run_sweep_over_ranks(a, *group);
  const Sweep sweep = read_sweep(a.file);  // every input error before the first render
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = a.threads > 0 ? a.threads : std::max(1, cores / a.jobs);
  Progress progress{!a.quiet && isatty(STDERR_FILENO) != 0, sweep.jobs.size()};
  if (progress.on)
    fmt::print(stderr, "sweep {}: {} jobs, {} at a time, {} threads each\n", a.file, sweep.jobs.size(), a.jobs,
               threads);
  const std::vector<JobResult> results = run_jobs(sweep, a.jobs, threads, progress);
  write_sweep_table(sweep, results);
  size_t failed = 0;
  for (const JobResult& r : results) failed += r.status == JobStatus::Failed;
  if (progress.on)
    fmt::print(stderr, "sweep: table {}{}\n", sweep.table, failed ? fmt::format(", {} failed", failed) : "");
  if (g_signal != 0) return 128 + g_signal;
  return failed ? 1 : 0;
}

const char* kSweepFooter = R"(The sweep file is JSON (docs/sweeps.md):
  {"scene": "scene.pbrt", "camera": "Camera \"navarro\" \"float fov\" 40",
   "output": "out/sweep", "spp": 64, "resolution": "256x256", "seed": 1,
   "vary": {"float pupildiameter": [3, 5], "float accommodation": [0, 1, 2]}}
Each job is `eyetrace render` in its own process, writing <output>/<name>.exr (name from the
varied values, e.g. accommodation-1_pupildiameter-3), <name>.json (statistics) and, if it
failed, <name>.log. A job whose output and statistics already hold the same scene and options
is skipped. The table <output>/<sweep file stem>.csv is written at the end.

Interrupting: the first SIGINT or SIGTERM stops starting jobs and tells the running renders to
stop (each writes its image so far and its state), writes the table and exits with 130 / 143.
Run the sweep again to finish it.

Exit status: 0 every job done or skipped; 1 an error in the sweep file, the scene or the output
folder (nothing rendered), or some job failed (see the table); 2 bad command line; 130 / 143
interrupted.)";

}  // namespace

CommandRunner add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* c = app.add_subcommand("sweep", "Render every combination of camera parameters listed in a sweep file");
  c->footer(kSweepFooter);
  c->add_option("sweepfile", args->file, "Sweep file (JSON; see below)")->required();
  c->add_option("-j,--jobs", args->jobs, "Renders run at the same time, each in its own process (default 1)")
      ->check(CLI::Range(1, kMaxSlots));
  c->add_option("--threads", args->threads, "Threads per render (default: the cores divided among the jobs)")
      ->check(CLI::Range(1, 1024));
  c->add_flag("-q,--quiet", args->quiet, "No progress (there is none either when stderr is not a terminal)");
  return [args] { return run_sweep(*args); };
}

}  // namespace eyetrace
