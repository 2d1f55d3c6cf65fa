// `eyetrace check`: every error and warning of a scene, with the place written in the scene
// text, missing files marked as such, and the exit status that tells the three outcomes apart
// (0 nothing to report, 1 errors, 3 warnings only).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/eyetrace_process.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::run_eyetrace;
using test::RunResult;
using test::TempDir;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name)) << text;
  return dir.file(name);
}

bool has_line(const std::string& output, const std::string& line) {
  return ("\n" + output).find("\n" + line + "\n") != std::string::npos;
}

TEST(CheckCommand, CleanSceneExitsZero) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "ok.pbrt", "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, scene + ": 0 errors (0 missing files), 0 warnings: ok\n");
}

TEST(CheckCommand, WarningsOnlyExitThree) {
  TempDir dir("eyetrace-check");
  const std::string scene =
      write(dir, "w.pbrt", "WorldBegin\nAttribute \"medium\" \"float g\" 0.5\nShape \"sphere\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_TRUE(has_line(r.output, scene + ":2:1: warning: Attribute \"medium\" (defaults for MakeNamedMedium) is not "
                                         "supported; ignored"))
      << r.output;
}

// A deprecated form read as written (pbrt-v3's TransformBegin, which pbrt-v4 also only warns
// about) ignores nothing: it is listed, but the scene renders as written, so the exit is 0.
TEST(CheckCommand, DeprecatedFormsAreListedButExitZero) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "d.pbrt",
                                  "WorldBegin\nTransformBegin\nTranslate 1 0 0\nShape \"sphere\"\nTransformEnd\n"
                                  "LightSource \"point\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has_line(r.output, scene + ":2:1: warning: TransformBegin/TransformEnd are deprecated (pbrt-v3); use "
                                         "AttributeBegin/AttributeEnd"))
      << r.output;
  EXPECT_TRUE(has_line(r.output, scene + ": 0 errors (0 missing files), 0 warnings (and 1 about deprecated forms): ok"))
      << r.output;
  const RunResult j = run_eyetrace("check --json " + scene);
  EXPECT_EQ(j.status, 0) << j.output;
  const nlohmann::json doc = nlohmann::json::parse(j.output);
  ASSERT_EQ(doc["diagnostics"].size(), 1u) << j.output;
  EXPECT_TRUE(doc["diagnostics"][0]["deprecated"].get<bool>());
  // --strict fails on warnings about what is ignored, not on this.
  const RunResult s = run_eyetrace("render --strict -q --spp 1 --resolution 4x4 -o " + dir.file("d.exr") + " " + scene);
  EXPECT_EQ(s.status, 0) << s.output;
}

// An object whose meshes are missing (as in pbrt-v4's transparent-machines frames, checked
// without their geometry): every missing mesh of the object is listed, not only the first, and
// its uses add nothing, since the object exists and its errors are said where they are.
TEST(CheckCommand, ObjectWithMissingMeshesListsEachMeshOnce) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "o.pbrt",
                                  "WorldBegin\nLightSource \"point\"\nObjectBegin \"arm\"\n"
                                  "Shape \"plymesh\" \"string filename\" \"a.ply\"\n"
                                  "Shape \"plymesh\" \"string filename\" \"b.ply\"\nObjectEnd\n"
                                  "ObjectInstance \"arm\"\nTranslate 1 0 0\nObjectInstance \"arm\"\n");
  const RunResult r = run_eyetrace("check --json " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  const nlohmann::json doc = nlohmann::json::parse(r.output);
  ASSERT_EQ(doc["diagnostics"].size(), 2u) << r.output;
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(doc["diagnostics"][i]["missing_file"].get<bool>()) << r.output;
    EXPECT_EQ(doc["diagnostics"][i]["line"].get<int>(), 4 + i) << r.output;
  }
}

// A sphere stretched into an ellipsoid is exact to intersect and shade; only sampling it as an
// area light is approximate, so only an emitting one is warned about (disney-cloud's medium
// boundary, an ellipsoid that does not emit, renders exactly: exit 0).
TEST(CheckCommand, StretchedSphereIsWarnedAboutOnlyWhenItEmits) {
  TempDir dir("eyetrace-check");
  const std::string head = "WorldBegin\nLightSource \"point\"\nScale 1 2 3\n";
  const RunResult plain = run_eyetrace("check " + write(dir, "p.pbrt", head + "Shape \"sphere\"\n"));
  EXPECT_EQ(plain.status, 0) << plain.output;
  const std::string lit = write(dir, "l.pbrt", head + "AreaLightSource \"diffuse\"\nShape \"sphere\"\n");
  const RunResult emitting = run_eyetrace("check " + lit);
  EXPECT_EQ(emitting.status, 3) << emitting.output;
  EXPECT_TRUE(has_line(emitting.output, lit + ":5:1: warning: Shape \"sphere\" as an area light: the transform scales "
                                              "non-uniformly; area sampling treats the ellipsoid as if uniformly "
                                              "scaled, so its density is approximate"))
      << emitting.output;
}

// Errors of every stage in one run, in the order of the text: a parameter the Film does not
// know, a missing Include (the parse goes on), a texture and a material eyetrace does not
// have, a missing PLY mesh, and an unused parameter of a material that names the failed
// texture (checked because the texture gets a stand-in), with the warning in between.
TEST(CheckCommand, ListsEveryErrorAndWarningWithItsPlace) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "s.pbrt",
                                  "Film \"rgb\" \"float bogus\" 2\n"
                                  "Include \"missing.pbrt\"\n"
                                  "WorldBegin\n"
                                  "Texture \"t\" \"spectrum\" \"nosuchtexture\"\n"
                                  "Material \"nosuchmaterial\"\n"
                                  "Shape \"sphere\"\n"
                                  "Attribute \"medium\" \"float g\" 0.5\n"
                                  "Shape \"plymesh\" \"string filename\" \"geo/a.ply\"\n"
                                  "Material \"diffuse\" \"texture reflectance\" \"t\" \"float bumpiness\" 1\n"
                                  "Shape \"sphere\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  const std::vector<std::string> expected = {
      scene + ":1:12: error: Film \"rgb\": unused parameter \"float bogus\"",
      scene + ":2:1: error: Include \"missing.pbrt\": file not found",
      scene + ":4:1: error: unsupported spectrum texture \"nosuchtexture\"",
      scene + ":5:1: error: unsupported material \"nosuchmaterial\"",
      scene + ":7:1: warning: Attribute \"medium\" (defaults for MakeNamedMedium) is not supported",
      scene + ":8:17: error: parameter \"filename\": cannot open",
      scene + ":9:46: error: Material \"diffuse\": unused parameter \"float bumpiness\"",
      scene + ": 6 errors (2 missing files), 1 warning: it does not render",
  };
  size_t at = 0;
  for (const std::string& e : expected) {
    size_t found = r.output.find(e, at);
    ASSERT_NE(found, std::string::npos) << "missing or out of order: " << e << "\n" << r.output;
    at = found + e.size();
  }
}

// More than the 20 errors a render lists: check lists them all.
TEST(CheckCommand, ListsMoreThanTwentyErrors) {
  TempDir dir("eyetrace-check");
  std::string text = "WorldBegin\n";
  for (int i = 0; i < 30; ++i) text += "Shape \"nosuchshape" + std::to_string(i) + "\"\n";
  const std::string scene = write(dir, "many.pbrt", text);
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(scene + ":31:1: error: unsupported shape \"nosuchshape29\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": 30 errors (0 missing files), 0 warnings"), std::string::npos) << r.output;
}

TEST(CheckCommand, JsonMarksMissingFiles) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "m.pbrt",
                                  "WorldBegin\nShape \"plymesh\" \"string filename\" \"absent.ply\"\n"
                                  "Shape \"nosuchshape\"\n");
  const RunResult r = run_eyetrace("check --json " + scene, false);
  EXPECT_EQ(r.status, 1) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["diagnostics"].size(), 2u) << r.output;
  EXPECT_EQ(j["diagnostics"][0]["line"], 2);
  EXPECT_EQ(j["diagnostics"][0]["missing_file"], true);
  EXPECT_EQ(j["diagnostics"][0]["parameter"], "filename");
  EXPECT_EQ(j["diagnostics"][1]["line"], 3);
  EXPECT_EQ(j["diagnostics"][1]["missing_file"], false);
}

// A realistic camera's lens file that is not there is missing data, like a mesh.
TEST(CheckCommand, AbsentLensFileIsAMissingFile) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "lens.pbrt",
                                  "Camera \"realistic\" \"string lensfile\" \"lenses/wide.22mm.dat\"\n"
                                  "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
  const RunResult r = run_eyetrace("check --json " + scene, false);
  EXPECT_EQ(r.status, 1) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["diagnostics"].size(), 1u) << r.output;
  EXPECT_EQ(j["diagnostics"][0]["missing_file"], true);
  EXPECT_EQ(j["diagnostics"][0]["parameter"], "lensfile");
  EXPECT_EQ(j["diagnostics"][0]["line"], 1);
}

// A parameter given twice with one type: pbrt-v4 uses the last value (tests/scene/params_test.cpp);
// check reports the first as dropped, a warning.
TEST(CheckCommand, RepeatedParameterIsAWarning) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "twice.pbrt",
                                  "Camera \"perspective\" \"float lensradius\" 1\n"
                                  "  \"float focaldistance\" 391 \"float focaldistance\" 114.5\n"
                                  "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(
      r.output.find(scene + ":2:29: warning: parameter \"focaldistance\" given again (first at " + scene + ":2:3)"),
      std::string::npos)
      << r.output;
}

// Film parameters pbrt-v4 would change the image with, and eyetrace ignores, are warnings.
// The film's sensor, white balance and clamp are used, not ignored: nothing to report.
TEST(CheckCommand, FilmSensorWhiteBalanceAndClampAreUsed) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "film.pbrt",
                                  "Film \"rgb\" \"string sensor\" \"nikon_d850\" \"float whitebalance\" 5000\n"
                                  "  \"float maxcomponentvalue\" 20 \"bool savefp16\" false\n"
                                  "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, scene + ": 0 errors (0 missing files), 0 warnings: ok\n");
}

// An unknown sensor, a negative white balance and a maximum of 0 are errors at their parameter.
TEST(CheckCommand, BadFilmSensorWhiteBalanceAndClampAreErrors) {
  TempDir dir("eyetrace-check");
  const struct {
    std::string film, where;
  } cases[] = {
      {"\"string sensor\" \"nikon_d900\"",
       ":1:12: error: parameter \"sensor\": unknown sensor \"nikon_d900\"; known: "
       "cie1931, canon_eos_100d,"},
      {"\"float whitebalance\" -10", ":1:12: error: parameter \"whitebalance\""},
      {"\"float whitebalance\" 20", ":1:12: error: parameter \"whitebalance\": 20 K: a light this cold"},
      {"\"float maxcomponentvalue\" 0", ":1:12: error: parameter \"maxcomponentvalue\""},
  };
  for (const auto& c : cases) {
    const std::string scene =
        write(dir, "bad.pbrt", "Film \"rgb\" " + c.film + "\nWorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
    const RunResult r = run_eyetrace("check " + scene);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(scene + c.where), std::string::npos) << r.output;
  }
}

// The gbuffer film renders (its EXR has the auxiliary channels) but refuses a checkpoint or a
// resume, whose render state would not hold its auxiliary sums.
TEST(CheckCommand, GBufferFilmRendersAndRefusesCheckpoints) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "gb.pbrt",
                                  "Film \"gbuffer\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                                  "Sampler \"independent\" \"integer pixelsamples\" 4\n"
                                  "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\n");
  EXPECT_EQ(run_eyetrace("check " + scene).status, 0);
  const RunResult ok = run_eyetrace("render " + scene + " --quiet -o " + dir.file("gb.exr"));
  EXPECT_EQ(ok.status, 0) << ok.output;
  for (const char* option : {" --checkpoint 10", " --resume"}) {
    const RunResult r = run_eyetrace("render " + scene + " --quiet -o " + dir.file("gb2.exr") + option);
    EXPECT_EQ(r.status, 1) << option << ": " << r.output;
    EXPECT_NE(r.output.find("the gbuffer film cannot be checkpointed"), std::string::npos) << r.output;
  }
}

// A shape whose mesh is missing still has its material checked.
TEST(CheckCommand, MaterialOfAShapeWithAMissingMeshIsChecked) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "mat.pbrt",
                                  "WorldBegin\nMaterial \"nosuchmaterial\"\n"
                                  "Shape \"plymesh\" \"string filename\" \"absent.ply\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(scene + ":2:1: error: unsupported material \"nosuchmaterial\""), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(": 2 errors (1 missing file), 0 warnings"), std::string::npos) << r.output;
}

// Every material is made, as pbrt-v4 does, even one no shape uses (here its shapes would be
// in a file that is missing); a missing spectrum file does not hide the material's type.
TEST(CheckCommand, EveryMaterialIsChecked) {
  TempDir dir("eyetrace-check");
  const std::string scene =
      write(dir, "all.pbrt",
            "WorldBegin\nMaterial \"nosuchmaterial\" \"spectrum eta\" \"spds/none.spd\"\n"
            "MakeNamedMaterial \"m\" \"string type\" \"conductor\" \"spectrum k\" \"spds/k.spd\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(scene + ":2:1: error: unsupported material \"nosuchmaterial\""), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(scene + ":3:49: error: parameter \"k\": spectrum file \"" + dir.file("spds/k.spd") +
                          "\" not found"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(": 2 errors (1 missing file), 0 warnings"), std::string::npos) << r.output;
}

// An unterminated string stops the parse: what follows cannot be read, nothing is built.
TEST(CheckCommand, UnterminatedStringStopsIt) {
  TempDir dir("eyetrace-check");
  const std::string scene = write(dir, "u.pbrt", "WorldBegin\nShape \"sphere\nShape \"nosuchshape\"\n");
  const RunResult r = run_eyetrace("check " + scene);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(scene + ":2:7: error: unterminated string"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nosuchshape\": "), std::string::npos) << r.output;
}

// Imported files large enough to be parsed on tasks of their own (ParseOptions'
// 256 KiB default), each with errors and a warning: the same listing at every run, each in
// its place, as the files read in order give it.
TEST(CheckCommand, ImportsOnTasksListTheSameDiagnosticsEveryRun) {
  TempDir dir("eyetrace-check");
  std::string points, indices;
  for (int i = 0; i < 12000; ++i) points += "0 0 0 1 0 0 0 1 0 ", indices += "0 1 2 ";
  for (int k = 0; k < 3; ++k)
    write(dir, "p" + std::to_string(k) + ".pbrt",
          "WorldEnd\nShape \"trianglemesh\" \"point3 P\" [" + points + "] \"integer indices\" [" + indices +
              "]\nScale 0 1 1\nShape \"sphere\" \"float radius\" -1\n");
  ASSERT_GE(std::filesystem::file_size(dir.file("p0.pbrt")), 256u * 1024u);
  const std::string scene = write(dir, "main.pbrt",
                                  "WorldBegin\nImport \"p0.pbrt\"\nRotate 1 0 0 0\nImport \"p1.pbrt\"\nWorldEnd\n"
                                  "Import \"p2.pbrt\"\nImport \"missing.pbrt\"\n");
  std::string expected = scene + ":3:1: error: Rotate: the rotation axis is the zero vector\n" + scene +
                         ":5:1: warning: WorldEnd is pbrt-v3 syntax and is ignored (pbrt-v4 scenes end at the end of "
                         "the file)\n" +
                         scene + ":7:1: error: Import \"missing.pbrt\": file not found (looked for \"" +
                         dir.file("missing.pbrt") + "\")\n";
  for (int k = 0; k < 3; ++k) {
    const std::string part = dir.file("p" + std::to_string(k) + ".pbrt");
    expected += part +
                ":1:1: warning: WorldEnd is pbrt-v3 syntax and is ignored (pbrt-v4 scenes end at the end of "
                "the file)\n" +
                part + ":3:1: error: Scale: a zero factor makes the transform singular\n" + part +
                ":4:16: error: parameter \"radius\": -1 is outside (0, inf)\n";
  }
  expected += scene + ": 8 errors (1 missing file), 4 warnings: it does not render\n";
  for (int run = 0; run < 5; ++run) {
    const RunResult r = run_eyetrace("check " + scene);
    EXPECT_EQ(r.status, 1) << r.output;
    ASSERT_EQ(r.output, expected) << "run " << run;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
