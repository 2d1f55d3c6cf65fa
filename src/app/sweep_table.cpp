// The sweep's CSV table (RFC 4180 quoting), written through a temporary file and a rename so a
// reader never sees half a table.
#include "app/sweep_table.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace eyetrace {

namespace {

std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

void write_sweep_table(const Sweep& sweep, const std::vector<JobResult>& results) {
  std::string text = "job";
  for (const std::string& v : sweep.varied) text += "," + field(v);
  text += ",output,status,error,render_seconds,spp\n";
  for (size_t i = 0; i < sweep.jobs.size(); ++i) {
    const SweepJob& job = sweep.jobs[i];
    const JobResult& r = results[i];
    text += field(job.name);
    for (const auto& [label, value] : job.values) text += "," + field(value);
    const bool ran = r.status == JobStatus::Done || r.status == JobStatus::Skipped;
    text += fmt::format(",{},{},{},{},{}\n", field(job.output), status_name(r.status), field(r.error),
                        ran ? fmt::format("{:.3f}", r.render_seconds) : "", ran ? std::to_string(r.spp) : "");
  }
  const std::string tmp = sweep.table + ".tmp";
  {
    std::ofstream f(tmp);
    f << text;
    if (!f) throw std::runtime_error(fmt::format("\"{}\": cannot write the table", tmp));
  }
  std::filesystem::rename(tmp, sweep.table);
}

}  // namespace eyetrace
