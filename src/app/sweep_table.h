// The results table of a sweep: one CSV row per job, written once at the end, atomically.
#pragma once
#include <vector>

#include "app/sweep.h"
#include "app/sweep_job.h"

namespace eyetrace {

// Columns: job, one per varied parameter, output, status, error, render_seconds, spp.
// Written to sweep.table through a temporary file and a rename.
void write_sweep_table(const Sweep& sweep, const std::vector<JobResult>& results);

}  // namespace eyetrace
