// One render over several MPI processes (src/distributed): the pixel data must be the bytes a
// single process writes, for 1, 2 and 3 ranks (oversubscribed on a small machine) and any thread
// count, uniform and adaptive; SIGINT to mpirun must leave the partial image and state that
// --resume finishes to the same bytes; a rank killed with SIGKILL must end the job with an error
// within seconds, never a hang, and --resume from the last checkpoint must finish the image.
// A build without MPI must refuse to run as one of several ranks.
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
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

std::vector<std::string> render_args(const std::string& output, const std::string& spp = "64",
                                     const std::string& threads = "1") {
  return {"render", kScene, "--resolution", "32x32", "--spp", spp, "--threads", threads,
          "--seed", "7",    "-q",           "-o",    output};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

bool same_pixels(const std::string& a, const std::string& b) {
  const Image x = read_image(a), y = read_image(b);
  return x.width == y.width && x.height == y.height && x.channels == y.channels &&
         std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)) == 0;
}

#if EYETRACE_WITH_MPI

// Samples per pixel of the renders that are interrupted: 128 passes of 8 after the first
// checkpoint, about a second on two cores in Release, so a signal or a killed rank lands
// mid-render (4096 made the two tests that use it the heaviest of the Release suite's fast tests).
const std::string kLongSpp = "1024";

// The eyetrace processes mpirun started (its children named eyetrace), from /proc.
std::vector<pid_t> eyetrace_children(pid_t parent) {
  std::vector<pid_t> kids;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(e.path() / "stat");
    std::string pid, comm, state;
    long ppid = 0;
    if (stat >> pid >> comm >> state >> ppid && ppid == parent && comm == "(eyetrace)") kids.push_back(std::stoi(pid));
  }
  return kids;
}

TEST(MpiRender, OneTwoAndThreeRanksGiveTheSingleProcessBytes) {
  TempDir dir("eyetrace_mpi");
  const std::string ref = dir.file("ref.exr");
  ASSERT_EQ(test::run_eyetrace_logged(render_args(ref, "64", "2"), dir.file("ref.log")), 0);
  for (int ranks : {1, 2, 3}) {
    const std::string out = dir.file("out" + std::to_string(ranks) + ".exr"), log = dir.file("mpi.log");
    ASSERT_EQ(run_mpirun(ranks, render_args(out), log), 0) << read_text(log);
    EXPECT_TRUE(same_pixels(out, ref)) << ranks << " ranks";
  }
  // Tiles dealt out in blocks instead of interleaved: the same bytes too.
  const std::string blocks = dir.file("blocks.exr");
  ASSERT_EQ(run_mpirun(3, with(render_args(blocks), {"--mpi-split", "blocks"}), dir.file("blocks.log")), 0)
      << read_text(dir.file("blocks.log"));
  EXPECT_TRUE(same_pixels(blocks, ref));
}

// A finished render gathers image values, not film sums (RenderGroup::collect_image): with a
// spectral film (R, G, B and 16 buckets per pixel) and a crop window whose tiles are cut at its
// edges, 2 and 3 ranks still write the single process's bytes.
TEST(MpiRender, SpectralFilmAndCroppedTilesGiveTheSingleProcessBytes) {
  TempDir dir("eyetrace_mpi_spectral");
  std::string scene = read_text(kScene);
  const size_t film = scene.find("Film \"rgb\"");
  ASSERT_NE(film, std::string::npos);
  scene.replace(film, std::string("Film \"rgb\"").size(), "Film \"spectral\" \"integer nbuckets\" 16");
  const std::string spectral = dir.file("spectral.pbrt");
  std::ofstream(spectral) << scene;
  const auto args = [&](const std::string& out, const std::string& threads) {
    return std::vector<std::string>{"render",           spectral, "--resolution", "45x37",     "--crop",
                                    "0.1,0.93,0.2,0.9", "--spp",  "16",           "--threads", threads,
                                    "--seed",           "3",      "-q",           "-o",        out};
  };
  const std::string ref = dir.file("ref.exr");
  ASSERT_EQ(test::run_eyetrace_logged(args(ref, "2"), dir.file("ref.log")), 0) << read_text(dir.file("ref.log"));
  ASSERT_EQ(read_image(ref).channels, 3 + 16);
  for (int ranks : {2, 3}) {
    const std::string out = dir.file("out" + std::to_string(ranks) + ".exr"), log = dir.file("mpi.log");
    ASSERT_EQ(run_mpirun(ranks, args(out, "1"), log), 0) << read_text(log);
    EXPECT_TRUE(same_pixels(out, ref)) << ranks << " ranks";
  }
}

// Ranks started with other arguments (mpirun's MPMD form: another seed on rank 1) would add
// other pixels to one film: refused before rendering, naming the rank; nothing is written.
TEST(MpiRender, RanksWithOtherOptionsAreRefused) {
  TempDir dir("eyetrace_mpi");
  const std::string out = dir.file("out.exr"), log = dir.file("mpi.log");
  std::vector<std::string> words = {"--oversubscribe", "-n", "1", test::eyetrace_binary()};
  for (const std::string& a : render_args(out)) words.push_back(a);
  words.insert(words.end(), {":", "-n", "1", test::eyetrace_binary()});
  std::vector<std::string> other = render_args(out);
  other[9] = "8";  // --seed
  words.insert(words.end(), other.begin(), other.end());
  test::allow_mpirun_as_root();
  const pid_t pid = test::spawn_logged("mpirun", words, log);
  ASSERT_GT(pid, 0);
  EXPECT_NE(test::wait_exit(pid), 0) << read_text(log);
  EXPECT_NE(read_text(log).find("rank 1 sees another scene or other options than rank 0"), std::string::npos)
      << read_text(log);
  EXPECT_FALSE(fs::exists(out));
}

TEST(MpiRender, AdaptiveRenderIsTheSameOverRanks) {
  TempDir dir("eyetrace_mpi");
  const std::vector<std::string> adaptive = {"--adaptive", "--target-error", "0.1", "--min-spp", "8"};
  const std::string ref = dir.file("ref.exr"), out = dir.file("out.exr"), stats = dir.file("stats.json");
  ASSERT_EQ(test::run_eyetrace_logged(with(render_args(ref, "256", "2"), adaptive), dir.file("ref.log")), 0);
  ASSERT_EQ(run_mpirun(3, with(render_args(out, "256"), with(adaptive, {"--stats", stats})), dir.file("mpi.log")), 0)
      << read_text(dir.file("mpi.log"));
  EXPECT_TRUE(same_pixels(out, ref));
  // --stats: every rank's time and the imbalance (the most loaded rank's busy time over the mean).
  const std::string json = read_text(stats);
  EXPECT_NE(json.find("\"count\": 3"), std::string::npos) << json;
  EXPECT_NE(json.find("\"load_imbalance\""), std::string::npos) << json;
}

TEST(MpiRender, SigintWritesThePartialImageAndResumeFinishesIt) {
  TempDir dir("eyetrace_mpi");
  const std::string out = dir.file("out.exr"), ref = dir.file("ref.exr"), log = dir.file("mpi.log");
  const std::vector<std::string> args = render_args(out, kLongSpp);
  const pid_t pid = spawn_mpirun(2, with(args, {"--checkpoint", "0", "--pass-samples", "8"}), log);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(test::wait_for_file(out + ".state", pid)) << read_text(log);
  kill(pid, SIGINT);
  EXPECT_NE(test::wait_exit(pid), 0) << read_text(log);
  ASSERT_TRUE(fs::exists(out + ".state")) << read_text(log);
  EXPECT_EQ(read_image_attribute(out, "eyetrace:interrupted"), "1") << read_text(log);
  ASSERT_EQ(run_mpirun(3, with(args, {"--resume"}), dir.file("resume.log")), 0) << read_text(dir.file("resume.log"));
  ASSERT_EQ(test::run_eyetrace_logged(render_args(ref, kLongSpp, "2"), dir.file("ref.log")), 0);
  EXPECT_TRUE(same_pixels(out, ref));
  EXPECT_FALSE(fs::exists(out + ".state"));
}

TEST(MpiRender, AKilledRankEndsTheJobWithinSecondsAndResumeFinishesIt) {
  TempDir dir("eyetrace_mpi");
  const std::string out = dir.file("out.exr"), ref = dir.file("ref.exr"), log = dir.file("mpi.log");
  const std::vector<std::string> args = render_args(out, kLongSpp);
  const pid_t pid = spawn_mpirun(2, with(args, {"--checkpoint", "0", "--pass-samples", "8"}), log);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(test::wait_for_file(out + ".state", pid)) << read_text(log);
  const std::vector<pid_t> ranks = eyetrace_children(pid);
  ASSERT_EQ(ranks.size(), 2u) << read_text(log);
  const auto t0 = std::chrono::steady_clock::now();
  kill(ranks.back(), SIGKILL);
  // A hang would never return: wait at most 60 s, then fail and clean up.
  int status = -1;
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
    int s = 0;
    if (waitpid(pid, &s, WNOHANG) == pid) {
      status = WIFEXITED(s) ? WEXITSTATUS(s) : 1000 + WTERMSIG(s);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (status == -1) {
    kill(pid, SIGKILL);
    test::wait_exit(pid);
    FAIL() << "the job hung after a rank was killed; log:\n" << read_text(log);
  }
  EXPECT_NE(status, 0);
  EXPECT_LT(seconds, 30.0);
  EXPECT_NE(read_text(log).find("exited on signal 9"), std::string::npos) << read_text(log);
  // The last checkpoint is whole (written through a rename) and finishes the image.
  ASSERT_EQ(run_mpirun(2, with(args, {"--resume"}), dir.file("resume.log")), 0) << read_text(dir.file("resume.log"));
  ASSERT_EQ(test::run_eyetrace_logged(render_args(ref, kLongSpp, "2"), dir.file("ref.log")), 0);
  EXPECT_TRUE(same_pixels(out, ref));
}

#else

TEST(MpiRender, ABuildWithoutMpiRefusesToBeOneOfSeveralRanks) {
  TempDir dir("eyetrace_mpi");
  setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  const int code = test::run_eyetrace_logged(render_args(dir.file("out.exr")), dir.file("log"));
  unsetenv("OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(code, 1);
  EXPECT_NE(read_text(dir.file("log")).find("built without MPI"), std::string::npos) << read_text(dir.file("log"));
  EXPECT_FALSE(fs::exists(dir.file("out.exr")));
}

#endif

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
