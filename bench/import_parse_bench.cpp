// Parsing Imports on tasks against parsing them in place (ParseOptions::import_task_min_bytes),
// by the size of the imported files: where a task stops paying is the default threshold
// (docs/performance.md, "Big scenes"). Each scene Imports 8 files holding one text
// trianglemesh of about the given size; wall time, since the point is parallelism.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>

#include <unistd.h>

#include "scene/parser.h"

namespace {

namespace fs = std::filesystem;
constexpr int kImports = 8;

// The generated files, removed when the program ends.
struct Scenes {
  std::map<size_t, std::string> made;
  fs::path root = fs::temp_directory_path() / ("eyetrace-import-bench-" + std::to_string(::getpid()));
  ~Scenes() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

// A directory with main.pbrt importing kImports files of about `bytes` each (made once).
std::string scene_of(size_t bytes) {
  static Scenes scenes;
  std::map<size_t, std::string>& made = scenes.made;
  if (auto it = made.find(bytes); it != made.end()) return it->second;
  fs::path dir = scenes.root / std::to_string(bytes);
  fs::create_directories(dir);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  std::ofstream main(dir / "main.pbrt");
  main << "WorldBegin\n";
  for (int k = 0; k < kImports; ++k) {
    std::string name = "part" + std::to_string(k) + ".pbrt";
    main << "Import \"" << name << "\"\n";
    std::ofstream part(dir / name);
    // 9 numbers of ~10 characters per triangle's points, 3 indices of ~7.
    const size_t triangles = std::max<size_t>(1, bytes / 110);
    part << "Shape \"trianglemesh\" \"point3 P\" [";
    for (size_t i = 0; i < 3 * triangles; ++i) part << u(rng) << ' ' << u(rng) << ' ' << u(rng) << ' ';
    part << "] \"integer indices\" [";
    for (size_t i = 0; i < 3 * triangles; ++i) part << i << ' ';
    part << "]\n";
  }
  return made[bytes] = (dir / "main.pbrt").string();
}

void parse(benchmark::State& state, std::uintmax_t min_bytes) {
  const std::string path = scene_of(size_t(state.range(0)));
  eyetrace::ParseOptions options;
  options.import_task_min_bytes = min_bytes;
  for (auto _ : state) benchmark::DoNotOptimize(eyetrace::parse_scene_file(path, options));
  state.SetBytesProcessed(int64_t(state.iterations()) * kImports * state.range(0));
}

void BM_ImportsOnTasks(benchmark::State& state) { parse(state, 0); }
void BM_ImportsInPlace(benchmark::State& state) { parse(state, std::numeric_limits<std::uintmax_t>::max()); }

}  // namespace

BENCHMARK(BM_ImportsOnTasks)->RangeMultiplier(8)->Range(1 << 10, 1 << 22)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ImportsInPlace)->RangeMultiplier(8)->Range(1 << 10, 1 << 22)->UseRealTime()->Unit(benchmark::kMicrosecond);
