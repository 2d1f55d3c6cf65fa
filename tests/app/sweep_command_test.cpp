// `eyetrace sweep`: a sweep file expanded into renders, each run as its own process, with
// outputs named from the varied values, a CSV table, finished outputs skipped on a rerun, a
// failing job reported without stopping the others, and input errors before any render. The
// program runs as a child process (tests/support/eyetrace_process.h); expected names, values and
// images come from the sweep file and from plain `eyetrace render` runs, not from the sweep code.
#include <signal.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/eyetrace_process.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;
using test::read_text;
using test::run_eyetrace;
using test::shell_quote;
using test::TempDir;

const std::string kScene = EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt";

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) row.push_back(f);
    if (!line.empty() && line.back() == ',') row.push_back("");
    rows.push_back(row);
  }
  return rows;
}

// A 2x2 sweep of the perspective camera on an 8x8 Cornell box, 4 samples per pixel.
std::string two_by_two(const std::string& output = "out", const std::string& fov = "[30, 40]") {
  return R"({"scene": ")" + kScene + R"(", "camera": "Camera \"perspective\"", "output": ")" + output +
         R"(", "spp": 4, "resolution": "8x8", "seed": 3,
           "vary": {"float fov": )" +
         fov + R"(, "float lensradius": [0, 0.05]}})";
}

const std::vector<std::string> kNames = {"fov-30_lensradius-0", "fov-30_lensradius-0.05", "fov-40_lensradius-0",
                                         "fov-40_lensradius-0.05"};

TEST(Sweep, TwoByTwoRendersFourNamedOutputsAndATable) {
  TempDir dir("eyetrace_sweep");
  write_text(dir.file("s.json"), two_by_two());
  test::RunResult r = run_eyetrace("sweep " + shell_quote(dir.file("s.json")));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto rows = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"job", "fov", "lensradius", "output", "status", "error",
                                               "render_seconds", "spp"}));
  const std::vector<std::vector<std::string>> values = {{"30", "0"}, {"30", "0.05"}, {"40", "0"}, {"40", "0.05"}};
  for (size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE(kNames[i]);
    EXPECT_EQ(rows[i + 1][0], kNames[i]);
    EXPECT_EQ(rows[i + 1][1], values[i][0]);
    EXPECT_EQ(rows[i + 1][2], values[i][1]);
    EXPECT_EQ(rows[i + 1][3], dir.file("out/" + kNames[i] + ".exr"));
    EXPECT_EQ(rows[i + 1][4], "done");
    EXPECT_EQ(rows[i + 1][7], "4");
    EXPECT_TRUE(fs::exists(dir.file("out/" + kNames[i] + ".json")));
  }
  // The job's image is the one `eyetrace render` gives with the same options.
  const std::string direct = dir.file("direct.exr");
  r = run_eyetrace("render " + shell_quote(kScene) +
                   " --camera 'Camera \"perspective\" \"float fov\" 40 \"float lensradius\" 0.05'"
                   " --spp 4 --resolution 8x8 --seed 3 -q -o " +
                   shell_quote(direct));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_image(direct).pixels, read_image(dir.file("out/fov-40_lensradius-0.05.exr")).pixels);
}

TEST(Sweep, RerunSkipsFinishedOutputsWithoutRendering) {
  TempDir dir("eyetrace_sweep");
  write_text(dir.file("s.json"), two_by_two());
  ASSERT_EQ(run_eyetrace("sweep -q " + shell_quote(dir.file("s.json"))).status, 0);
  std::vector<fs::file_time_type> before;
  for (const std::string& n : kNames) before.push_back(fs::last_write_time(dir.file("out/" + n + ".exr")));
  const test::RunResult r = run_eyetrace("sweep -q " + shell_quote(dir.file("s.json")));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto rows = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 5u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(rows[i + 1][4], "skipped") << kNames[i];
    EXPECT_EQ(fs::last_write_time(dir.file("out/" + kNames[i] + ".exr")), before[i]) << kNames[i];
  }
  // Another seed makes other images: nothing is skipped.
  std::string text = two_by_two();
  text.replace(text.find("\"seed\": 3"), 9, "\"seed\": 4");
  write_text(dir.file("s.json"), text);
  ASSERT_EQ(run_eyetrace("sweep -q " + shell_quote(dir.file("s.json"))).status, 0);
  const auto rerun = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rerun.size(), 5u);
  for (size_t i = 1; i < 5; ++i) EXPECT_EQ(rerun[i][4], "done") << rerun[i][0];
}

TEST(Sweep, AFailingJobIsReportedAndTheOthersFinish) {
  TempDir dir("eyetrace_sweep");
  write_text(dir.file("s.json"), two_by_two("out", "[30, 200]"));  // fov must be below 180 deg
  const test::RunResult r = run_eyetrace("sweep -q " + shell_quote(dir.file("s.json")));
  EXPECT_EQ(r.status, 1) << r.output;
  const auto rows = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 5u);
  for (size_t i = 1; i < 5; ++i) {
    const bool bad = rows[i][1] == "200";
    EXPECT_EQ(rows[i][4], bad ? "failed" : "done") << rows[i][0];
    EXPECT_EQ(fs::exists(dir.file("out/" + rows[i][0] + ".exr")), !bad) << rows[i][0];
    if (bad) EXPECT_NE(rows[i][5].find("fov"), std::string::npos) << rows[i][5];
  }
}

TEST(Sweep, LocalProcessesGiveTheSameBytesAsOne) {
  TempDir dir("eyetrace_sweep");
  write_text(dir.file("one.json"), two_by_two("one"));
  write_text(dir.file("two.json"), two_by_two("two"));
  ASSERT_EQ(run_eyetrace("sweep -q --jobs 1 " + shell_quote(dir.file("one.json"))).status, 0);
  ASSERT_EQ(run_eyetrace("sweep -q --jobs 2 " + shell_quote(dir.file("two.json"))).status, 0);
  // The pixel data, bit for bit (the EXR header also holds the time it was written).
  for (const std::string& n : kNames) {
    const Image a = read_image(dir.file("one/" + n + ".exr")), b = read_image(dir.file("two/" + n + ".exr"));
    EXPECT_EQ(a.pixels.size(), 8u * 8u * 3u) << n;
    EXPECT_TRUE(a.pixels.size() == b.pixels.size() &&
                std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0)
        << n;
  }
}

TEST(Sweep, AnUnknownKeyIsAnErrorBeforeAnyRender) {
  TempDir dir("eyetrace_sweep");
  std::string text = two_by_two();
  text.replace(text.find("\"vary\""), 6, "\"vray\"");
  write_text(dir.file("s.json"), text);
  const test::RunResult r = run_eyetrace("sweep " + shell_quote(dir.file("s.json")));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("unknown key \"vray\" (did you mean \"vary\"?)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(dir.file("s.json")), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Sweep, AnUnknownCameraParameterIsAnErrorBeforeAnyRender) {
  TempDir dir("eyetrace_sweep");
  std::string text = two_by_two();
  text.replace(text.find("float fov"), 9, "float fvo");
  write_text(dir.file("s.json"), text);
  const test::RunResult r = run_eyetrace("sweep " + shell_quote(dir.file("s.json")));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("has no parameter \"fvo\" (did you mean \"fov\"?)"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Sweep, AnOutputFolderThatCannotBeMadeIsAnErrorBeforeAnyRender) {
  TempDir dir("eyetrace_sweep");
  write_text(dir.file("file"), "not a folder");
  write_text(dir.file("s.json"), two_by_two(dir.file("file/out")));
  const test::RunResult r = run_eyetrace("sweep " + shell_quote(dir.file("s.json")));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("output folder \"" + dir.file("file/out") + "\""), std::string::npos) << r.output;
}

TEST(Sweep, AnInterruptedSweepLeavesNoHalfWrittenFileAndARerunFinishesIt) {
  TempDir dir("eyetrace_sweep");
  // Three renders of about a quarter of a second each on one thread (Release; six times that
  // under the sanitizers), so the signal, sent within milliseconds of the first render's end,
  // lands mid-sweep. (512 samples per pixel made this the sanitizer run's second-heaviest test.)
  write_text(dir.file("s.json"), R"({"scene": ")" + kScene + R"(", "camera": "Camera \"perspective\"",
      "output": "out", "spp": 128, "resolution": "32x32", "seed": 1, "vary": {"float fov": [30, 35, 40]}})");
  const int status = test::run_eyetrace_and_signal({"sweep", "--threads", "1", dir.file("s.json")}, dir.file("log"),
                                                   dir.file("out/fov-30.json"), SIGINT);
  EXPECT_EQ(status, 130) << read_text(dir.file("log"));
  auto rows = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1][3], "done");
  // The signal lands in the second render, or (on a loaded machine) just before it starts.
  EXPECT_TRUE(rows[2][3] == "interrupted" || rows[2][3] == "not run") << read_text(dir.file("out/s.csv"));
  EXPECT_EQ(rows[3][3], "not run");
  for (const auto& entry : fs::directory_iterator(dir.file("out")))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  ASSERT_EQ(run_eyetrace("sweep -q " + shell_quote(dir.file("s.json"))).status, 0);
  rows = read_csv(dir.file("out/s.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1][3], "skipped");
  EXPECT_EQ(rows[2][3], "done");
  EXPECT_EQ(rows[3][3], "done");
  for (const char* n : {"fov-30", "fov-35", "fov-40"}) {
    EXPECT_EQ(read_image_attribute(dir.file(std::string("out/") + n + ".exr"), "eyetrace:interrupted"), "0") << n;
    EXPECT_FALSE(fs::exists(dir.file(std::string("out/") + n + ".exr.state"))) << n;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
