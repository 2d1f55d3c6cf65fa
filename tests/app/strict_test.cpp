// The command line and diagnostics: several scene errors print one line each and a count,
// exit 1 and write nothing; a warning lets the render go on, and with --strict it is an error
// that stops it before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/eyetrace_process.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

using test::run_eyetrace;
using test::RunResult;

fs::path write(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(CommandLine, SeveralSceneErrorsArePrintedAndNothingIsWritten) {
  const fs::path scene = write("eyetrace-strict-errors.pbrt", "WorldBegin\nLightSource \"pointt\"\nShape \"spher\"\n");
  const fs::path out = fs::temp_directory_path() / "eyetrace-strict-errors.exr";
  fs::remove(out);
  const RunResult r = run_eyetrace("render -q " + scene.string() + " -o " + out.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output,
            scene.string() + ":3:1: error: unsupported shape \"spher\" (did you mean \"sphere\"?); " +
                "eyetrace supports: bilinearmesh, curve, cylinder, disk, loopsubdiv, plymesh, sphere, trianglemesh\n" +
                scene.string() +
                ":2:1: error: unsupported light \"pointt\" (did you mean \"point\"?); eyetrace supports: "
                "distant, goniometric, infinite, point, projection, spot\n2 errors\n");
  EXPECT_FALSE(fs::exists(out));
  fs::remove(scene);
}

TEST(CommandLine, StrictMakesWarningsFatal) {
  // "regularize" is accepted and ignored with a warning.
  const fs::path scene = write("eyetrace-strict-warning.pbrt",
                               "Integrator \"path\" \"bool regularize\" true\nWorldBegin\nShape \"sphere\"\n");
  const fs::path out = fs::temp_directory_path() / "eyetrace-strict-warning.exr";
  fs::remove(out);
  const std::string base = "render " + scene.string() + " -o " + out.string() + " --resolution 8x8 --spp 1";
  RunResult r = run_eyetrace(base);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(":1:1: warning: \"regularize\" is not supported; ignored"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);

  r = run_eyetrace(base + " --strict");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(":1:1: error: \"regularize\" is not supported; ignored (a warning, fatal with --strict)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(scene);
}

TEST(CommandLine, BadOptionsExitTwo) {
  const RunResult r = run_eyetrace("render scene.pbrt --resolution 0x3");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--resolution: \"0x3\": expected WxH"), std::string::npos) << r.output;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
