// A parameter sweep (`eyetrace sweep SWEEPFILE`, docs/sweeps.md): the JSON sweep file parsed and
// validated into a list of independent render jobs, each a full set of `render` options and an
// output path. Nothing here runs a job: the local scheduler (sweep_command.cpp) and a later MPI
// one hand the same jobs out.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace eyetrace {

// One render of the sweep: what `eyetrace render` is given, and the values that make it.
struct SweepJob {
  std::string name;                                         // "pupildiameter-3_accommodation-1": the output's stem
  std::vector<std::pair<std::string, std::string>> values;  // varied key -> value as written, in key order
  std::string camera;                                       // the full Camera directive
  int spp = 0;                                              // 0: the scene's
  std::string resolution;                                   // "WxH"; "": the scene's
  int64_t seed = -1;                                        // < 0: the scene's
  std::string output;                                       // <output dir>/<name>.<format>
  std::string stats;                                        // <output dir>/<name>.json: the render's statistics
  std::string log;                                          // <output dir>/<name>.log: the render's messages
  uint64_t key = 0;  // fingerprint of the scene and every option that changes the image (skip test)

  // The `eyetrace render` arguments (after "render") that make this job's image, writing its
  // statistics to `stats_path` and using `threads` threads (0: the render's default).
  std::vector<std::string> render_args(const std::string& scene, const std::string& stats_path, int threads) const;
};

struct Sweep {
  std::string file;                 // the sweep file, as given
  std::string scene;                // resolved against the sweep file's folder
  std::string output_dir;           // resolved likewise; created and checked writable
  std::vector<std::string> varied;  // the varied keys, sorted: the CSV's value columns
  std::string table;                // <output dir>/<sweep file stem>.csv
  std::vector<SweepJob> jobs;       // the cartesian product, the last key varying fastest
};

// Reads, checks and expands `path`. Every mistake (unreadable or malformed file, unknown key,
// a camera parameter the camera does not have or of the wrong type, a scene error, an output
// folder that cannot be written) throws std::runtime_error naming the file and key before any
// job runs. A parameter value a camera refuses is the job's own failure, found when it renders.
Sweep read_sweep(const std::string& path);

}  // namespace eyetrace
