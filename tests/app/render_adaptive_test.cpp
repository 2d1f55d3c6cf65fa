// `eyetrace render --adaptive`: bad options are named, SIGINT and --resume give the image an
// uninterrupted adaptive render gives, bit for bit, and --stats / --spp-image report the samples
// each pixel took, consistently with each other.
#include <signal.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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
using test::TempDir;

const std::string kScene = EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt";

// Target 0.15 with a cap of 256: pixels stop anywhere from 16 to 256 samples (33 of the 1024
// take the cap), 70 per pixel on average, 13 times fewer than target 0.05 with a cap of 1024,
// which kept almost every pixel at 512 or 1024 (the sanitizer build's heaviest test).
std::vector<std::string> adaptive_args(const std::string& output, const std::string& threads = "1") {
  return {"render", kScene, "--resolution", "32x32",          "--max-spp", "256",       "--threads", threads, "--seed",
          "7",      "-q",   "--adaptive",   "--target-error", "0.15",      "--min-spp", "8",         "-o",    output};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(RenderAdaptive, BadOptionsNameTheOption) {
  struct Case {
    std::string args, expected;
  } cases[] = {
      {"--adaptive --target-error 0", "--target-error: \"0\": must be a number in (0, 1000)"},
      {"--adaptive --target-error -1", "--target-error: \"-1\": must be a number in (0, 1000)"},
      {"--adaptive --target-error nan", "--target-error: \"nan\": must be a number in (0, 1000)"},
      {"--target-error 0.01", "--target-error: needs --adaptive"},
      {"--max-spp 64", "--max-spp: needs --adaptive"},
      {"--adaptive --max-spp 8", "--max-spp: 8 is below --min-spp 16"},
      {"--adaptive --max-spp 64 --spp 32", "--max-spp: differs from --spp"},
      {"--adaptive --spp-image counts.png", "\"counts.png\": the sample-count image is written as .exr"},
  };
  for (const Case& c : cases) {
    const test::RunResult r = test::run_eyetrace("render " + test::shell_quote(kScene) + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
}

TEST(RenderAdaptive, AStratifiedSamplerIsRefused) {
  TempDir dir("eyetrace_adaptive");
  const std::string scene = dir.file("stratified.pbrt");
  std::ofstream(scene) << "Sampler \"stratified\" \"integer xsamples\" 4 \"integer ysamples\" 4\n"
                       << "Camera \"perspective\"\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                       << "WorldBegin\nShape \"sphere\"\n";
  const test::RunResult s =
      test::run_eyetrace("render " + test::shell_quote(scene) + " --adaptive -q -o " + dir.file("s.exr"));
  EXPECT_EQ(s.status, 1) << s.output;
  EXPECT_NE(s.output.find("--adaptive"), std::string::npos) << s.output;
  EXPECT_NE(s.output.find("stratified"), std::string::npos) << s.output;
  EXPECT_FALSE(fs::exists(dir.file("s.exr")));
}

TEST(RenderAdaptive, SigintAndResumeGiveTheUninterruptedImage) {
  TempDir dir("eyetrace_adaptive");
  const std::string out = dir.file("out.exr"), ref = dir.file("ref.exr");
  const int code = test::run_eyetrace_and_signal(with(adaptive_args(out), {"--checkpoint", "0"}),
                                                 dir.file("interrupted.log"), out + ".state", SIGINT);
  EXPECT_EQ(code, 130) << read_text(dir.file("interrupted.log"));
  ASSERT_TRUE(fs::exists(out + ".state")) << read_text(dir.file("interrupted.log"));
  EXPECT_EQ(read_image_attribute(out, "eyetrace:interrupted"), "1");

  EXPECT_EQ(test::run_eyetrace_logged(with(adaptive_args(out, "2"), {"--resume"}), dir.file("resume.log")), 0)
      << read_text(dir.file("resume.log"));
  EXPECT_EQ(test::run_eyetrace_logged(adaptive_args(ref), dir.file("ref.log")), 0) << read_text(dir.file("ref.log"));
  EXPECT_FALSE(fs::exists(out + ".state"));
  const Image a = read_image(out), b = read_image(ref);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);

  // Resuming with other adaptive options is another render: refused.
  EXPECT_EQ(test::run_eyetrace_and_signal(with(adaptive_args(out), {"--checkpoint", "0"}), dir.file("again.log"),
                                          out + ".state", SIGINT),
            130);
  std::vector<std::string> other = adaptive_args(out);
  other[13] = "0.2";  // --target-error
  EXPECT_EQ(test::run_eyetrace_logged(with(other, {"--resume"}), dir.file("other.log")), 1);
  EXPECT_NE(read_text(dir.file("other.log")).find("was made for another scene or other options"), std::string::npos)
      << read_text(dir.file("other.log"));
}

TEST(RenderAdaptive, StatsAndSppImageAgree) {
  TempDir dir("eyetrace_adaptive");
  const std::string out = dir.file("out.exr"), counts = dir.file("spp.exr"), stats = dir.file("stats.json");
  ASSERT_EQ(
      test::run_eyetrace_logged(with(adaptive_args(out), {"--stats", stats, "--spp-image", counts}), dir.file("log")),
      0)
      << read_text(dir.file("log"));
  const nlohmann::json j = nlohmann::json::parse(read_text(stats));
  const nlohmann::json& d = j["samples_per_pixel_distribution"];
  const Image img = read_image(counts);
  ASSERT_EQ(img.channels, 1);
  ASSERT_EQ(img.pixels.size(), 32u * 32u);
  double sum = 0;
  float lo = 1e9f, hi = 0;
  for (float v : img.pixels) {
    sum += v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_EQ(lo, d["min"].get<double>());
  EXPECT_EQ(hi, d["max"].get<double>());
  EXPECT_GE(lo, 8.f) << "every pixel takes the first pass";
  EXPECT_LE(hi, 256.f);
  EXPECT_LT(lo, hi) << "the Cornell box has pixels that stop early and pixels that take the cap";
  EXPECT_DOUBLE_EQ(sum / img.pixels.size(), d["mean"].get<double>());
  EXPECT_DOUBLE_EQ(sum, double(j["samples"].get<uint64_t>()));
  size_t pixels = 0;
  for (const auto& h : d["histogram"]) pixels += h["pixels"].get<size_t>();
  EXPECT_EQ(pixels, 32u * 32u);
  EXPECT_EQ(j["adaptive"]["target_error"].get<double>(), 0.15);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
