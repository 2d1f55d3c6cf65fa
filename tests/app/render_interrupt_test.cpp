// `eyetrace render` stopped by SIGINT or SIGTERM: it must write the image so far (marked
// interrupted, with the samples it holds), exit 130 or 143, and `--resume` must then finish
// the same image an uninterrupted render gives, bit for bit. The program is started as a
// child process; signals are sent once its first checkpoint exists (never after a fixed
// sleep), so the tests hold on a loaded machine.
#include <signal.h>

#include <cmath>
#include <cstdlib>
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

const std::string kScene = EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt";

// A 32x32 Cornell box at 256 samples per pixel: about a second of one thread (a minute under
// AddressSanitizer on a busy machine), so the first checkpoint (8 samples, 3% of the work)
// comes early and the render is far from done when the signal lands.
std::vector<std::string> render_args(const std::string& output, const std::string& spp = "256",
                                     const std::string& seed = "7", const std::string& threads = "1") {
  return {"render", kScene,   "--resolution", "32x32", "--spp", spp,   "--threads",
          threads,  "--seed", seed,           "-q",    "-o",    output};
}

using test::read_text;
using test::TempDir;

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Renders with checkpoints after every pass of 8 samples, and sends `sig` once the first
// checkpoint is on disk. Returns the exit status (1000 + a signal that killed it).
int render_and_interrupt(const std::string& output, int sig, const std::string& log) {
  return test::run_eyetrace_and_signal(with(render_args(output), {"--checkpoint", "0", "--pass-samples", "8"}), log,
                                       output + ".state", sig);
}

bool all_finite(const Image& img) {
  for (float v : img.pixels)
    if (!std::isfinite(v)) return false;
  return true;
}

bool bit_identical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// The interrupted image: marked, fewer samples than asked for, no NaN; the state is kept.
void expect_interrupted_output(const std::string& output, const std::string& log) {
  ASSERT_TRUE(fs::exists(output)) << read_text(log);
  EXPECT_TRUE(fs::exists(output + ".state"));
  EXPECT_EQ(read_image_attribute(output, "eyetrace:interrupted"), "1");
  EXPECT_EQ(read_image_attribute(output, "eyetrace:samples_requested"), "256");
  int spp = std::stoi("0" + read_image_attribute(output, "eyetrace:samples_per_pixel"));
  EXPECT_GE(spp, 8);
  EXPECT_LT(spp, 256);
  EXPECT_EQ(spp % 8, 0) << "passes of 8 samples";
  Image img = read_image(output);
  EXPECT_EQ(img.width, 32);
  EXPECT_TRUE(all_finite(img));
  EXPECT_NE(read_text(log).find("continue with --resume"), std::string::npos) << read_text(log);
}

TEST(RenderInterrupt, SigintWritesPartialImageAndResumeMatchesUninterruptedRender) {
  TempDir dir("eyetrace_interrupt");
  std::string out = dir.file("out.exr"), ref = dir.file("ref.exr");
  int code = render_and_interrupt(out, SIGINT, dir.file("interrupted.log"));
  EXPECT_EQ(code, 130) << read_text(dir.file("interrupted.log"));
  expect_interrupted_output(out, dir.file("interrupted.log"));

  // Resume with another thread count and adaptive passes: neither may change a bit.
  EXPECT_EQ(test::run_eyetrace_logged(with(render_args(out, "256", "7", "2"), {"--resume"}), dir.file("resume.log")), 0)
      << read_text(dir.file("resume.log"));
  EXPECT_EQ(test::run_eyetrace_logged(render_args(ref), dir.file("ref.log")), 0) << read_text(dir.file("ref.log"));
  EXPECT_EQ(read_image_attribute(out, "eyetrace:interrupted"), "0");
  EXPECT_EQ(read_image_attribute(out, "eyetrace:samples_per_pixel"), "256");
  EXPECT_FALSE(fs::exists(out + ".state")) << "a finished render leaves no state behind";
  EXPECT_TRUE(bit_identical(read_image(out), read_image(ref)));
}

TEST(RenderInterrupt, SigtermWritesPartialImageAndExits143) {
  TempDir dir("eyetrace_interrupt");
  std::string out = dir.file("out.exr");
  int code = render_and_interrupt(out, SIGTERM, dir.file("interrupted.log"));
  EXPECT_EQ(code, 143) << read_text(dir.file("interrupted.log"));
  expect_interrupted_output(out, dir.file("interrupted.log"));
}

// --resume refuses a state that is missing or belongs to another render, and keeps it.
TEST(RenderInterrupt, ResumeRefusesMissingOrMismatchedState) {
  TempDir dir("eyetrace_interrupt");
  std::string out = dir.file("out.exr");
  EXPECT_EQ(test::run_eyetrace_logged(with(render_args(out), {"--resume"}), dir.file("missing.log")), 1);
  EXPECT_NE(read_text(dir.file("missing.log")).find("render state \"" + out + ".state\" not found"), std::string::npos)
      << read_text(dir.file("missing.log"));
  EXPECT_FALSE(fs::exists(out));

  EXPECT_EQ(render_and_interrupt(out, SIGINT, dir.file("interrupted.log")), 130);
  const std::string state = read_text(out + ".state");
  EXPECT_EQ(test::run_eyetrace_logged(with(render_args(out, "64"), {"--resume"}), dir.file("spp.log")), 1);
  EXPECT_NE(read_text(dir.file("spp.log")).find("is for 256 samples per pixel, this render asks for 64"),
            std::string::npos)
      << read_text(dir.file("spp.log"));
  EXPECT_EQ(test::run_eyetrace_logged(with(render_args(out, "256", "8"), {"--resume"}), dir.file("seed.log")), 1);
  EXPECT_NE(read_text(dir.file("seed.log")).find("was made for another scene or other options"), std::string::npos)
      << read_text(dir.file("seed.log"));
  EXPECT_EQ(read_text(out + ".state"), state) << "a refused resume must not touch the state";
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
