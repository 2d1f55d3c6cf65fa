// `mpirun -n N eyetrace sweep` (src/distributed/sweep_group.h): rank 0 hands the jobs out, the
// others render them; the outputs must be the bytes a local sweep writes, the table the same, a
// failing job reported without stopping the others, and a rerun must skip what is done. A build
// without MPI must refuse to be one of several sweep ranks.
#include <signal.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/eyetrace_process.h"
#include "../support/mpirun.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;
using test::read_text;
using test::TempDir;
#if EYETRACE_WITH_MPI
using test::run_mpirun;
using test::spawn_mpirun;
#endif

const std::string kScene = EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt";

// A 2x2 sweep of the perspective camera on an 8x8 Cornell box (fov 200 is refused by the camera).
std::string two_by_two(const std::string& output, const std::string& fovs) {
  return R"({"scene": ")" + kScene + R"(", "camera": "Camera \"perspective\"", "output": ")" + output +
         R"(", "spp": 4, "resolution": "8x8", "seed": 3, "vary": {"float fov": )" + fovs +
         R"(, "float lensradius": [0, 0.05]}})";
}

// The table's rows after the header, each as its fields (the error field may hold commas: only
// the first five fields are used).
std::vector<std::vector<std::string>> table_rows(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::istringstream fields(line);
    for (std::string f; row.size() < 5 && std::getline(fields, f, ',');) row.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

bool same_pixels(const std::string& a, const std::string& b) {
  const Image x = read_image(a), y = read_image(b);
  return x.pixels.size() == y.pixels.size() &&
         std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)) == 0;
}

#if EYETRACE_WITH_MPI

TEST(MpiSweep, RanksRenderTheLocalSweepsBytesAndReportAFailingJob) {
  TempDir dir("eyetrace_mpi_sweep");
  std::ofstream(dir.file("local.json")) << two_by_two(dir.file("local"), "[30, 40]");
  std::ofstream(dir.file("ranks.json")) << two_by_two(dir.file("ranks"), "[30, 40]");
  ASSERT_EQ(test::run_eyetrace_logged({"sweep", "-q", dir.file("local.json")}, dir.file("local.log")), 0)
      << read_text(dir.file("local.log"));
  ASSERT_EQ(run_mpirun(3, {"sweep", "-q", dir.file("ranks.json")}, dir.file("ranks.log")), 0)
      << read_text(dir.file("ranks.log"));
  const auto local = table_rows(dir.file("local/local.csv")), ranks = table_rows(dir.file("ranks/ranks.csv"));
  ASSERT_EQ(ranks.size(), 4u);
  ASSERT_EQ(local.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(ranks[i][0], local[i][0]);
    EXPECT_EQ(ranks[i][4], "done") << ranks[i][0];
    EXPECT_TRUE(same_pixels(dir.file("ranks/" + ranks[i][0] + ".exr"), dir.file("local/" + local[i][0] + ".exr")))
        << ranks[i][0];
  }
  // Run again: everything is skipped, nothing rendered.
  ASSERT_EQ(run_mpirun(2, {"sweep", "-q", dir.file("ranks.json")}, dir.file("again.log")), 0)
      << read_text(dir.file("again.log"));
  for (const auto& row : table_rows(dir.file("ranks/ranks.csv"))) EXPECT_EQ(row[4], "skipped") << row[0];

  // fov 200 is refused by the camera: those two jobs fail, the other two finish, exit 1.
  std::ofstream(dir.file("bad.json")) << two_by_two(dir.file("bad"), "[30, 200]");
  EXPECT_NE(run_mpirun(3, {"sweep", "-q", dir.file("bad.json")}, dir.file("bad.log")), 0);
  const auto bad = table_rows(dir.file("bad/bad.csv"));
  ASSERT_EQ(bad.size(), 4u) << read_text(dir.file("bad.log"));
  for (const auto& row : bad) {
    const bool refused = row[1] == "200";
    EXPECT_EQ(row[4], refused ? "failed" : "done") << row[0];
    EXPECT_EQ(fs::exists(dir.file("bad/" + row[0] + ".exr")), !refused) << row[0];
  }
}

// Ctrl-C (SIGINT to mpirun, passed on to every rank): no more jobs are handed out, the renders
// under way write their image so far and state, and rank 0 writes the table with them marked
// interrupted and the rest not run; nothing is half-written.
TEST(MpiSweep, SigintStopsTheSweepAndWritesTheTable) {
  TempDir dir("eyetrace_mpi_sweep");
  std::string text = two_by_two(dir.file("out"), "[30, 35, 40]");
  const std::string spp = "\"spp\": 4,";
  // Long enough (seconds per job) that a loaded machine cannot finish every job before the
  // signal reaches the ranks.
  text.replace(text.find(spp), spp.size(), "\"spp\": 65536,");
  std::ofstream(dir.file("s.json")) << text;
  const pid_t pid = spawn_mpirun(3, {"sweep", "-q", "--threads", "1", dir.file("s.json")}, dir.file("log"));
  ASSERT_GT(pid, 0);
  // Once a render has started (its log exists), interrupt.
  ASSERT_TRUE(test::wait_for_file(dir.file("out/fov-30_lensradius-0.log"), pid)) << read_text(dir.file("log"));
  kill(pid, SIGINT);
  EXPECT_NE(test::wait_exit(pid), 0);
  const auto rows = table_rows(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 6u) << read_text(dir.file("log"));
  size_t interrupted = 0, not_run = 0;
  for (const auto& row : rows) {
    interrupted += row[4] == "interrupted";
    not_run += row[4] == "not run";
  }
  EXPECT_GE(interrupted, 1u);
  EXPECT_GE(not_run, 1u);
  for (const auto& e : fs::directory_iterator(dir.file("out")))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(MpiSweep, AnUnreadableSweepFileIsAnErrorBeforeAnyRender) {
  TempDir dir("eyetrace_mpi_sweep");
  EXPECT_NE(run_mpirun(2, {"sweep", "-q", dir.file("missing.json")}, dir.file("log")), 0);
  EXPECT_NE(read_text(dir.file("log")).find("missing.json"), std::string::npos) << read_text(dir.file("log"));
}

#else

TEST(MpiSweep, ABuildWithoutMpiRefusesToBeOneOfSeveralSweepRanks) {
  TempDir dir("eyetrace_mpi_sweep");
  std::ofstream(dir.file("s.json")) << two_by_two(dir.file("out"), "[30, 40]");
  setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  const int code = test::run_eyetrace_logged({"sweep", "-q", dir.file("s.json")}, dir.file("log"));
  unsetenv("OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(code, 1);
  EXPECT_NE(read_text(dir.file("log")).find("built without MPI"), std::string::npos) << read_text(dir.file("log"));
  EXPECT_FALSE(fs::exists(dir.file("out")));
}

#endif

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
