// Spectrum files ("spectrum eta" "au_eta.spd"), read by the parser as pbrt-v4 does, relative
// to the top-level scene's directory: the pairs are those of the file (six samples of pbrt-v4's
// Au_eta, so metal-Au-eta agrees at them), and a file that is missing or malformed is an error
// naming the parameter, the file and, for a bad value, its line (a missing one where the
// parameter is read).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "core/named_spectra.h"
#include "scene/parser.h"
#include "scene/spectrum_param.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;
using test::TempDir;

const fs::path kSpectra = fs::path(EYETRACE_SOURCE_DIR) / "tests" / "data" / "spectra";

std::string scene(const std::string& eta) {
  return "WorldBegin\nMaterial \"conductor\" \"spectrum eta\" \"" + eta + "\" \"spectrum k\" \"metal-Au-k\"\n" +
         "Shape \"sphere\"\n";
}

Diagnostic error_of(const std::string& text, const std::string& dir) {
  try {
    parse_scene_string(text, "s.pbrt", dir);
  } catch (const SceneError& e) {
    return e.first();
  }
  return Diagnostic{};
}

TEST(SpectrumFile, PairsAreTheFilesAndMatchTheNamedSpectrum) {
  SceneDescription d = parse_scene_string(scene("au_eta.spd"), "s.pbrt", kSpectra.string());
  const Param* eta = d.materials.back().params.find("eta");
  ASSERT_NE(eta, nullptr);
  EXPECT_TRUE(eta->strings.empty());
  const std::vector<double> want = {427.532, 1.616,    486.212, 1.086750, 551.041, 0.345500,
                                    619.921, 0.194000, 688.801, 0.160000, 751.419, 0.169500};
  ASSERT_EQ(eta->numbers.size(), want.size());
  const NamedSpectrum& au = *find_named_spectrum("metal-Au-eta");
  for (size_t i = 0; i < want.size(); i += 2) {
    EXPECT_DOUBLE_EQ(eta->numbers[i], want[i]);
    EXPECT_DOUBLE_EQ(eta->numbers[i + 1], want[i + 1]);
    EXPECT_NEAR(evaluate_named_spectrum(au, float(want[i])), want[i + 1], 1e-5);
  }
}

// Relative to the top-level scene's directory, also from an included file elsewhere.
TEST(SpectrumFile, ResolvedAgainstTheSceneDirectory) {
  TempDir dir("eyetrace-spd");
  fs::create_directories(dir.path() / "spds" / "sub");
  fs::copy_file(kSpectra / "au_eta.spd", dir.path() / "spds" / "au.spd");
  std::ofstream(dir.file("spds/sub/inc.pbrt")) << scene("spds/au.spd");
  std::ofstream(dir.file("main.pbrt")) << "Include \"spds/sub/inc.pbrt\"\n";
  SceneDescription d = parse_scene_file(dir.file("main.pbrt"));
  EXPECT_EQ(d.materials.back().params.find("eta")->numbers.size(), 12u);
}

// A file that is not there does not fail the directive (so `eyetrace check` goes on with it):
// its path stays in the parameter, and reading the parameter is the missing-file error.
TEST(SpectrumFile, MissingFileIsAMissingFileErrorWhereItIsRead) {
  SceneDescription d = parse_scene_string(scene("spds/none.spd"), "s.pbrt", kSpectra.string());
  const Param* eta = d.materials.back().params.find("eta");
  ASSERT_NE(eta, nullptr);
  const std::string path = (kSpectra / "spds/none.spd").string();
  ASSERT_EQ(eta->strings, std::vector<std::string>{path});
  try {
    spectrum_param_value(*eta, SpectrumType::Unbounded);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.first().kind, DiagnosticKind::MissingFile);
    EXPECT_EQ(e.first().parameter, "eta");
    EXPECT_EQ(e.first().loc.to_string(), "s.pbrt:2:22");
    EXPECT_EQ(e.first().message, "parameter \"eta\": spectrum file \"" + path + "\" not found");
  }
}

TEST(SpectrumFile, MalformedFilesNameTheLine) {
  TempDir dir("eyetrace-spd");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"400 1\n500 x\n", "line 2: \"x\" is not a finite number"},
      {"400 1\n500\n", "needs (wavelength, value) pairs, at least two; it has 3 numbers"},
      {"400 1\n", "needs (wavelength, value) pairs, at least two; it has 2 numbers"},
      {"400 1\n# c\n400 2\n", "line 3: wavelengths must be positive and increasing (got 400 nm)"},
      {"400 1\n500 nan\n", "line 2: \"nan\" is not a finite number"},
  };
  for (const auto& [text, why] : cases) {
    std::ofstream(dir.file("bad.spd")) << text;
    const Diagnostic e = error_of(scene("bad.spd"), dir.path().string());
    EXPECT_EQ(e.kind, DiagnosticKind::General) << text;
    EXPECT_EQ(e.message, "parameter \"eta\": spectrum file \"" + dir.file("bad.spd") + "\": " + why) << text;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
