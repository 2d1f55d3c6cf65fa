// Running one sweep job: in a child process that execs this eyetrace binary with the job's
// `render` arguments, so that a job that crashes, runs out of memory or leaves global state
// (warning flags, signal handlers) behind cannot take the sweep or the next job with it. The
// same start/finish pair serves the local scheduler now and an MPI worker rank later.
#pragma once
#include <sys/types.h>

#include <string>

#include "app/sweep.h"

namespace eyetrace {

enum class JobStatus { Done, Skipped, Failed, Interrupted, NotRun };
const char* status_name(JobStatus s);  // "done", "skipped", "failed", "interrupted", "not run"

struct JobResult {
  JobStatus status = JobStatus::NotRun;
  std::string error;          // failed: the first error line the render printed
  double render_seconds = 0;  // from the render's statistics (skipped: those of the earlier run)
  int spp = 0;
};

// A job is already done when its output exists and its statistics carry the job's key (written
// only after the render finished): the same scene and options made it. Fills `result` if so.
bool already_done(const SweepJob& job, JobResult& result);

// Forks and execs `eyetrace render ...` for `job` in its own process group (a Ctrl-C at the
// terminal reaches the sweep, which passes it on once), with its output in job.log. Returns the
// child's pid; throws when the process cannot be started.
pid_t start_job(const Sweep& sweep, const SweepJob& job, int threads);

// The job's result from its child's wait status; on success writes job.stats (with the key)
// atomically and removes the log.
JobResult finish_job(const SweepJob& job, int wait_status);

}  // namespace eyetrace
