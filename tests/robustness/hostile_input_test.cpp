// The hostile-input catalogue of issue 6: inputs a user (or a broken exporter) can get wrong,
// each of which must end in a clear error naming file:line:col and the parameter, or in a
// documented clamp; never in a crash, an exception other than SceneError, or a NaN in the image.
// In-process through parse_scene_string + build_render_setup; whole-program behaviour (exit
// codes, output files) through the built binary. docs/robustness.md lists every case.
#include <signal.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../support/eyetrace_process.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "core/error.h"
#include "render/image_io.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

// Rendering options for an 8x8, 1 spp image: six lines, so the world starts on line 7.
const char* kOptions = R"(LookAt 0 0 -5  0 0 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 8 "integer yresolution" 8 "string filename" "out.exr"
Sampler "independent" "integer pixelsamples" 1
Integrator "path" "integer maxdepth" 3
PixelFilter "box"
)";

// kOptions + "WorldBegin\n" + world: the world text starts on line 8.
std::string in_world(const std::string& world) { return std::string(kOptions) + "WorldBegin\n" + world; }

// Parses and builds; returns the SceneError message, or "" when the scene is accepted.
// Any other exception is a finding: it fails the test and its text is returned.
std::string build_error(const std::string& text, const RenderOverrides& overrides = {},
                        const std::string& search_dir = "/") {
  set_warnings_enabled(false);
  try {
    SceneDescription desc = parse_scene_string(text, "hostile.pbrt", search_dir);
    RenderSetup setup = build_render_setup(desc, overrides);
    return "";
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a SceneError: " << e.what() << "\nfor input:\n" << text;
    return std::string("unexpected exception: ") + e.what();
  }
}

struct RenderResult {
  uint64_t nonfinite_samples = 0;
  int nonfinite_pixels = 0;
};

// Renders an accepted scene (8x8, 1 spp, one thread).
RenderResult render(const std::string& text) {
  set_warnings_enabled(false);
  SceneDescription desc = parse_scene_string(text, "hostile.pbrt", "/");
  RenderSetup setup = build_render_setup(desc, {});
  RenderCounters counters;
  RenderOptions options;
  options.threads = 1;
  options.progress = false;
  setup.integrator->render(*setup.camera, *setup.sampler, *setup.film, options, counters);
  RenderResult r;
  r.nonfinite_samples = counters.nonfinite_samples;
  for (float v : setup.film->image().pixels) r.nonfinite_pixels += !std::isfinite(v);
  return r;
}

#define EXPECT_ERROR(text, expected) EXPECT_PRED_FORMAT2(contains, build_error(text), expected)

testing::AssertionResult contains(const char*, const char*, const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "expected an error containing\n  " << part << "\ngot\n  "
                                     << (message.empty() ? "(accepted)" : message);
}

void write_file(const std::string& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
}

using test::read_text;
using test::TempDir;

// ---------------------------------------------------------------------------------------
// Truncated files and unbalanced blocks

// A valid scene using most directives, one per line (continuation lines are indented).
const char* kFullScene = R"(Option "integer seed" 3
ColorSpace "srgb"
LookAt 0 0 -5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
Film "rgb" "integer xresolution" [ 8 ] "integer yresolution" 8 "string filename" "out.exr"
Sampler "independent" "integer pixelsamples" 1
Integrator "path" "integer maxdepth" [ 3 ]
PixelFilter "box"
WorldBegin
LightSource "distant" "point3 from" [ 0 10 0 ] "point3 to" [ 0 0 0 ] "blackbody L" 5500
Texture "checks" "spectrum" "checkerboard" "float uscale" [ 8 ] "rgb tex1" [ .1 .1 .1 ] "rgb tex2" [ .9 .9 .9 ]
MakeNamedMaterial "gold" "string type" "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k"
AttributeBegin
Material "diffuse" "texture reflectance" "checks"
Translate 1 0 0
Rotate 30 0 1 0
Scale 1 2 1
Shape "trianglemesh" "point3 P" [ 0 0 0  1 0 0  0 1 0 ] "integer indices" [ 0 1 2 ]
AttributeEnd
AttributeBegin
NamedMaterial "gold"
AreaLightSource "diffuse" "rgb L" [ 4 4 4 ]
ReverseOrientation
Shape "sphere" "float radius" 0.5
AttributeEnd
ObjectBegin "ball"
Shape "sphere" "float radius" 0.1
ObjectEnd
ObjectInstance "ball"
CoordinateSystem "here"
CoordSysTransform "here"
Identity
ConcatTransform [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1 ]
Transform [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1 ]
Shape "disk" "float radius" 2
)";

bool takes_arguments(const std::string& directive) {
  for (const char* bare : {"AttributeBegin", "AttributeEnd", "WorldBegin", "ObjectEnd", "Identity",
                           "ReverseOrientation", "TransformBegin", "TransformEnd", "WorldEnd"})
    if (directive == bare) return false;
  return true;
}

std::string parse_error(const std::string& text, const std::string& file) {
  set_warnings_enabled(false);
  try {
    parse_scene_string(text, file, "/");
    return "";
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a SceneError: " << e.what() << "\nfor input:\n" << text;
    return "unexpected exception";
  }
}

TEST(HostileInput, TruncatedRightAfterEveryDirectiveNamesItsLine) {
  const std::string full = kFullScene;
  int line = 1, checked = 0;
  for (size_t start = 0; start < full.size(); start = full.find('\n', start) + 1, ++line) {
    size_t end = full.find_first_of(" \n", start);
    std::string directive = full.substr(start, end - start);
    if (!takes_arguments(directive)) continue;
    std::string message = parse_error(full.substr(0, end), "truncated.pbrt");
    EXPECT_NE(message.find(fmt::format("truncated.pbrt:{}:", line)), std::string::npos) << directive << ": " << message;
    EXPECT_NE(message.find("end of file"), std::string::npos) << directive << ": " << message;
    ++checked;
  }
  EXPECT_EQ(checked, 27);  // directives with arguments in kFullScene, counted by hand
}

TEST(HostileInput, TruncatedAtEveryByteIsASceneErrorOrAValidScene) {
  const std::string full = kFullScene;
  for (size_t n = 0; n < full.size(); ++n) {
    std::string message = parse_error(full.substr(0, n), "truncated.pbrt");
    if (!message.empty()) {
      EXPECT_EQ(message.rfind("truncated.pbrt", 0), 0u) << "cut at " << n << ": " << message;
      EXPECT_NE(message.find(": error: "), std::string::npos) << "cut at " << n << ": " << message;
    }
  }
}

TEST(HostileInput, TruncatedBeforeEveryDirectiveBuildsOrFailsCleanly) {
  const std::string full = kFullScene;
  EXPECT_EQ(build_error(full), "");  // the whole scene is valid
  for (size_t start = 0; start < full.size(); start = full.find('\n', start) + 1) {
    std::string message = build_error(full.substr(0, start));
    // A prefix is a scene of its own; it may be valid, but an error names the file.
    if (!message.empty()) EXPECT_EQ(message.rfind("hostile.pbrt", 0), 0u) << message;
  }
  EXPECT_ERROR(std::string(full.substr(0, full.find("WorldBegin"))),
               "hostile.pbrt: error: the scene ends before WorldBegin");
  EXPECT_ERROR(std::string(full.substr(0, full.find("AttributeEnd"))),
               "hostile.pbrt:13:1: error: AttributeBegin has no matching AttributeEnd before the end of the scene");
}

TEST(HostileInput, TruncatedInsideBracketsOrStrings) {
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0"),
               "hostile.pbrt:8:33: error: parameter \"point3 P\": '[' has no matching ']' before the end of the file");
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P"),
               "hostile.pbrt:8:22: error: unterminated string \"point3 P\": end of file before the closing quote");
  EXPECT_ERROR(in_world("Shape \"sphere\" \"float radius\""),
               "error: parameter \"float radius\" has no value: end of file");
}

TEST(HostileInput, UnbalancedBlocksAndBrackets) {
  EXPECT_ERROR(in_world("AttributeEnd\n"), "hostile.pbrt:8:1: error: AttributeEnd without a matching AttributeBegin");
  EXPECT_ERROR(in_world("AttributeBegin\nAttributeBegin\nAttributeEnd\n"),
               "hostile.pbrt:8:1: error: AttributeBegin has no matching AttributeEnd before the end of the scene");
  EXPECT_ERROR(in_world("TransformBegin\nAttributeEnd\n"),
               "hostile.pbrt:9:1: error: AttributeEnd does not match the TransformBegin at hostile.pbrt:8:1");
  EXPECT_ERROR(in_world("ObjectBegin \"a\"\n"), "hostile.pbrt:8:1: error: ObjectBegin has no matching ObjectEnd");
  EXPECT_ERROR(in_world("ObjectEnd\n"), "hostile.pbrt:8:1: error: ObjectEnd without a matching ObjectBegin");
  EXPECT_ERROR(in_world("Shape \"sphere\" \"float radius\" 1 ]\n"),
               "hostile.pbrt:8:33: error: unexpected ']' where a directive (Shape, AttributeBegin, ...) was expected");
  EXPECT_ERROR(in_world("Shape \"sphere\" \"float radius\" ]\n"),
               "hostile.pbrt:8:31: error: parameter \"float radius\": unexpected ']' (no matching '[')");
  EXPECT_ERROR(
      in_world("Shape \"sphere\" \"float radius\" [ [ 1 ] ]\n"),
      "hostile.pbrt:8:33: error: parameter \"float radius\": unexpected '[' (is the ']' for the '[' at 8:31 missing?)");
  EXPECT_ERROR(std::string(kOptions) + "AttributeBegin\nWorldBegin\n",
               "hostile.pbrt:7:1: error: AttributeBegin is only allowed after WorldBegin");
}

// ---------------------------------------------------------------------------------------
// Numbers: NaN, infinity, 1e308 in every parameter kind

struct Kind {
  const char* type;
  int tuple;
};
constexpr Kind kNumericKinds[] = {{"float", 1},   {"integer", 1}, {"point2", 2}, {"vector2", 2},  {"point3", 3},
                                  {"vector3", 3}, {"normal", 3},  {"rgb", 3},    {"spectrum", 1}, {"blackbody", 1}};

TEST(HostileInput, NonFiniteNumbersInEveryParameterKindAreParseErrors) {
  for (const Kind& k : kNumericKinds) {
    for (const char* bad : {"nan", "inf", "-inf", "NaN", "Infinity"}) {
      std::string values;
      for (int i = 0; i < k.tuple; ++i) values += i == k.tuple - 1 ? bad : "1 ";
      std::string decl = fmt::format("{} x", k.type);
      EXPECT_ERROR(in_world(fmt::format("Shape \"sphere\" \"{}\" [ {} ]\n", decl, values)),
                   fmt::format("error: parameter \"{}\": \"{}\" is not a finite number", decl, bad));
    }
    EXPECT_ERROR(in_world(fmt::format("Shape \"sphere\" \"{} x\" [ 1e999 ]\n", k.type)), "value 1e999 is out of range");
  }
  EXPECT_ERROR(in_world("Translate nan 0 0\n"), "hostile.pbrt:8:11: error: Translate: \"nan\" is not a finite number");
  EXPECT_ERROR(in_world("Rotate 10 0 inf 0\n"), "hostile.pbrt:8:13: error: Rotate: \"inf\" is not a finite number");
  EXPECT_ERROR(in_world("Scale 1 1 1e999\n"), "hostile.pbrt:8:11: error: Scale: value 1e999 is out of range");
  EXPECT_ERROR("LookAt 0 0 0  0 0 nan  0 1 0\nWorldBegin\n",
               "hostile.pbrt:1:19: error: LookAt: \"nan\" is not a finite number");
  EXPECT_ERROR(in_world("ConcatTransform [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 -inf ]\n"),
               "error: ConcatTransform: \"-inf\" is not a finite number");
}

// 1e308 is a finite double but beyond float: each kind as read by a real plugin parameter.
TEST(HostileInput, NumbersBeyondFloatRangeInEveryParameterKindAreErrors) {
  const std::string light = "LightSource \"distant\"\n";
  EXPECT_ERROR(in_world("Shape \"sphere\" \"float radius\" 1e308\n"),
               "hostile.pbrt:8:16: error: parameter \"radius\" value 1e+308 is out of the float range");
  EXPECT_ERROR(std::string("Film \"rgb\" \"integer xresolution\" 1e308\nWorldBegin\n"),
               "hostile.pbrt:1:34: error: parameter \"integer xresolution\": value 1e308 is not a 32-bit integer");
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [1e308 0 0 0 0 0]\n"),
               "parameter \"uv\" value 1e+308 is out of the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"point3 from\" [1e308 0 0]\n"),
               "hostile.pbrt:8:21: error: parameter \"from\" value 1e+308 is out of the float range");
  EXPECT_ERROR(
      in_world(
          "Texture \"t\" \"spectrum\" \"checkerboard\" \"string mapping\" \"planar\" \"vector3 v1\" [1e308 0 0]\n"),
      "parameter \"v1\" value 1e+308 is out of the float range");
  EXPECT_ERROR(
      in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"normal N\" [1e308 0 0 0 0 1 0 0 1]\n"),
      "parameter \"N\" value 1e+308 is out of the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"rgb I\" [1e308 1 1]\n"),
               "parameter \"I\" value 1e+308 is out of the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"spectrum I\" [400 1e308 700 1]\n"),
               "parameter \"I\" value 1e+308 is out of the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"blackbody I\" 1e308\n"),
               "parameter \"I\" value 1e+308 is out of the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"blackbody I\" 1e9\n"),
               "parameter \"I\": blackbody temperature 1000000000 K is outside [100, 1e7] K");
  // A vector2 parameter is read by no plugin: it is reported as unused.
  EXPECT_ERROR(in_world("Shape \"sphere\" \"vector2 x\" [1e308 0]\n" + light), "unused parameter \"vector2 x\"");
  EXPECT_ERROR(in_world("Translate 1e308 0 0\n"), "hostile.pbrt:8:11: error: Translate: value 1e308 is out of range");
  EXPECT_ERROR(std::string("Sampler \"independent\" \"integer pixelsamples\" 2147483648\nWorldBegin\n"),
               "value 2147483648 is not a 32-bit integer");
}

// Values inside float range whose products overflow: a light whose power leaves float range
// would never be chosen by the light sampler (and would light nothing but discarded samples);
// a transform that stretches lengths past 1e18 overflows squared lengths later, where the
// message would be misleading ("from" and "to" coincide). Both are errors at the directive.
TEST(HostileInput, OverflowingLightPowerIsAnErrorNamingTheParameter) {
  EXPECT_ERROR(in_world("LightSource \"distant\" \"float scale\" 1e30 \"rgb L\" [1e30 1e30 1e30]\nShape \"sphere\"\n"),
               "hostile.pbrt:8:23: error: parameter \"scale\": the light's power overflows the float range");
  EXPECT_ERROR(in_world("LightSource \"point\" \"rgb I\" [3e38 3e38 3e38]\n"),
               "hostile.pbrt:8:21: error: parameter \"I\": the light's power overflows the float range");
  // Finite radiance, but emitted over an area of 4 pi 1e38.
  EXPECT_ERROR(in_world("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                        "Shape \"sphere\" \"float radius\" 1e19\nAttributeEnd\n"),
               "hostile.pbrt:9:27: error: parameter \"L\": the light's power overflows the float range");
  // 1e30 alone is large but representable: accepted, and the image stays finite.
  RenderResult r = render(in_world("LightSource \"distant\" \"float scale\" 1e30\nShape \"sphere\"\n"));
  EXPECT_EQ(r.nonfinite_pixels, 0);
  EXPECT_EQ(r.nonfinite_samples, 0u);
}

TEST(HostileInput, OverflowingOrDegenerateTransformNamesTheDirective) {
  EXPECT_ERROR(in_world("Scale 1e20 1e20 1e20\nLightSource \"distant\"\n"),
               "hostile.pbrt:8:1: error: Scale makes the current transform overflow: it scales lengths by up to 1e+20");
  EXPECT_ERROR(
      in_world("Scale 1e-20 1e-20 1e-20\nShape \"sphere\"\n"),
      "hostile.pbrt:8:1: error: Scale makes the current transform degenerate: it scales lengths by as little as 1e-20");
  // Each factor is fine; the product overflows at the second directive.
  EXPECT_ERROR(in_world("Scale 1e10 1e10 1e10\nScale 1e10 1 1\n"),
               "hostile.pbrt:9:1: error: Scale makes the current transform overflow: it scales lengths by up to 1e+20");
  EXPECT_ERROR(in_world("Translate 1e19 0 0\n"),
               "hostile.pbrt:8:1: error: Translate makes the current transform "
               "overflow: it moves the origin 1e+19 away");
  EXPECT_ERROR(in_world("ConcatTransform [1e20 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1]\n"),
               "hostile.pbrt:8:1: error: ConcatTransform makes the current transform overflow");
  EXPECT_EQ(build_error(in_world("Scale 1e15 1e15 1e15\nLightSource \"distant\"\nShape \"sphere\"\n")), "");
}

// pbrt-v4: roughness must be >= 0. A negative constant was clamped to 0 (a mirror) silently.
TEST(HostileInput, NegativeRoughnessIsAnErrorNamingTheParameter) {
  EXPECT_ERROR(in_world("Material \"conductor\" \"float roughness\" -1\nShape \"sphere\"\n"),
               "hostile.pbrt:8:22: error: parameter \"roughness\": -1 is outside [0, inf)");
  EXPECT_ERROR(
      in_world("Material \"conductor\" \"float uroughness\" 0.1 \"float vroughness\" -0.5\nShape \"sphere\"\n"),
      "error: parameter \"vroughness\": -0.5 is outside [0, inf)");
  EXPECT_ERROR(in_world("Material \"dielectric\" \"float uroughness\" -0.01\nShape \"sphere\"\n"),
               "error: parameter \"uroughness\": -0.01 is outside [0, inf)");
  EXPECT_EQ(build_error(in_world("Material \"conductor\" \"float roughness\" 0\nShape \"sphere\"\n")), "");
}

// Optical constants given as numbers: a conductor's eta must be positive and its k
// non-negative (they were clamped silently); a spectrum value beyond float range is named.
TEST(HostileInput, ConductorOpticalConstantsAndHugeSpectrumValues) {
  EXPECT_ERROR(in_world("Material \"conductor\" \"spectrum eta\" [400 -1 700 -1]\nShape \"sphere\"\n"),
               "error: parameter \"eta\": must be positive (its smallest value here is");
  EXPECT_ERROR(in_world("Material \"conductor\" \"rgb k\" [1 -0.5 1]\nShape \"sphere\"\n"),
               "error: parameter \"k\": must be non-negative (its smallest value here is -0.5)");
  EXPECT_EQ(
      build_error(in_world("Material \"conductor\" \"rgb eta\" [0.2 0.9 1.1] \"rgb k\" [0 3 3]\nShape \"sphere\"\n")),
      "");
  EXPECT_ERROR(in_world("Material \"dielectric\" \"spectrum eta\" [400 1e308 700 1e308]\nShape \"sphere\"\n"),
               "error: parameter \"eta\" value 1e+308 is out of the float range");
}

// ---------------------------------------------------------------------------------------
// Shapes: negative sizes and indices, degenerate and empty meshes

TEST(HostileInput, NegativeRadiiAndIndices) {
  EXPECT_ERROR(in_world("Shape \"sphere\" \"float radius\" -1\n"),
               "hostile.pbrt:8:16: error: parameter \"radius\": -1 is outside (0, inf)");
  EXPECT_ERROR(in_world("Shape \"disk\" \"float radius\" -1\n"),
               "hostile.pbrt:8:14: error: parameter \"radius\": -1 is outside (0, inf)");
  EXPECT_ERROR(in_world("Shape \"disk\" \"float radius\" 1 \"float innerradius\" -1\n"),
               "parameter \"innerradius\": -1 is outside [0, inf)");
  EXPECT_ERROR(in_world("Material \"dielectric\" \"float eta\" -1.5\nShape \"sphere\"\n"),
               "hostile.pbrt:8:23: error: parameter \"eta\": -1.5 is outside (0, inf)");
  EXPECT_ERROR(
      in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 -1 2]\n"),
      "hostile.pbrt:8:53: error: parameter \"indices\": index -1 (entry 1) is out of range: there are 3 vertices");
  EXPECT_ERROR(std::string("Camera \"thinlens\" \"float lensradius\" -1\nWorldBegin\n"),
               "parameter \"lensradius\": -1 is outside [0, inf)");
}

TEST(HostileInput, ZeroAreaTrianglesAndDegenerateMeshes) {
  const char* error = "error: parameter \"P\": the mesh has no triangle of nonzero, finite area";
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 2 0 0]\n"), error);        // collinear
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [1 1 1 1 1 1 1 1 1]\n"), error);        // one point
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 3e38 0 0 0 3e38 0]\n"), error);  // area overflows
  EXPECT_ERROR(in_world("Shape \"bilinearmesh\" \"point3 P\" [0 0 0 0 0 0 0 0 0 0 0 0]\n"), error);
  // Some degenerate triangles among good ones: dropped with a warning, the rest renders.
  int warnings = warning_count();
  EXPECT_EQ(build_error(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 2 0 0]\n"
                                 "  \"integer indices\" [0 1 2 0 1 3]\n")),
            "");
  EXPECT_GT(warning_count(), warnings);
  // Zero shading normals fall back to the geometric normal.
  RenderResult r =
      render(in_world("LightSource \"distant\"\nShape \"trianglemesh\" \"point3 P\" [-5 -5 0 5 -5 0 0 5 0]\n"
                      "  \"normal N\" [0 0 0 0 0 0 0 0 0]\n"));
  EXPECT_EQ(r.nonfinite_samples, 0u);
}

TEST(HostileInput, IndicesOutOfRange) {
  const std::string tri = "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] ";
  EXPECT_ERROR(
      in_world(tri + "\"integer indices\" [0 1 3]\n"),
      "hostile.pbrt:8:53: error: parameter \"indices\": index 3 (entry 2) is out of range: there are 3 vertices");
  EXPECT_ERROR(in_world(tri + "\"integer indices\" [0 1]\n"),
               "parameter \"indices\": 2 vertex indices is not a multiple of 3");
  EXPECT_ERROR(in_world(tri + "\"integer indices\" [0 1 2147483647]\n"), "index 2147483647 (entry 2) is out of range");
  EXPECT_ERROR(in_world(tri + "\"normal N\" [0 0 1 0 0 1]\n"), "parameter \"N\": 2 normals given for 3 vertices");
  EXPECT_ERROR(in_world(tri + "\"point2 uv\" [0 0]\n"), "parameter \"uv\": 1 uv values given for 3 vertices");
  EXPECT_ERROR(
      in_world("Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0] \"integer indices\" [0 1 2 4]\n"),
      "parameter \"indices\": index 4 (entry 3) is out of range: there are 4 vertices");
}

TEST(HostileInput, EmptyMeshes) {
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" []\n"),
               "hostile.pbrt:8:22: error: parameter \"point3 P\" has no values");
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" []\n"),
               "parameter \"integer indices\" has no values");
  EXPECT_ERROR(in_world("Shape \"trianglemesh\"\n"),
               "hostile.pbrt:8:1: error: parameter \"P\": the mesh has no vertex positions");
  EXPECT_ERROR(in_world("Shape \"bilinearmesh\"\n"),
               "hostile.pbrt:8:1: error: parameter \"P\": the mesh has no vertex positions");
  EXPECT_ERROR(in_world("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 1]\n"),
               "parameter \"indices\": vertex indices are required unless the mesh has exactly 3 vertices (it has 4)");
}

// ---------------------------------------------------------------------------------------
// Files: recursive Include, lying PLY, broken measured BRDFs, textures that are not images

TEST(HostileInput, RecursiveInclude) {
  TempDir dir("eyetrace-hostile");
  write_file(dir.file("a.pbrt"), "Include \"b.pbrt\"\n");
  write_file(dir.file("b.pbrt"), "WorldBegin\n\nInclude \"a.pbrt\"\n");
  write_file(dir.file("self.pbrt"), "WorldBegin\nImport \"self.pbrt\"\n");
  auto error_of = [](const std::string& path) -> std::string {
    try {
      parse_scene_file(path);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  std::string message = error_of(dir.file("a.pbrt"));
  EXPECT_NE(message.find("b.pbrt:3:1: error: recursive Include of \"" + dir.file("a.pbrt") +
                         "\" (a.pbrt -> b.pbrt -> a.pbrt)"),
            std::string::npos)
      << message;
  message = error_of(dir.file("self.pbrt"));
  EXPECT_NE(message.find("self.pbrt:2:1: error: recursive Import of"), std::string::npos) << message;
  EXPECT_ERROR(in_world("Include \"/\"\n"), "hostile.pbrt:8:1: error: cannot read scene file \"/\": it is a directory");
  EXPECT_ERROR(in_world("Include \"no-such-file.pbrt\"\n"),
               "hostile.pbrt:8:1: error: Include \"no-such-file.pbrt\": file not found");
}

std::string ply_header(const char* format, int64_t vertices, int faces) {
  return fmt::format(
      "ply\nformat {} 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      format, vertices, faces);
}

TEST(HostileInput, PlyThatLiesAboutItsSize) {
  TempDir dir("eyetrace-hostile");
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string three(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  struct Case {
    const char* name;
    std::string content;
    const char* message;
  };
  const Case cases[] = {
      // The header promises 1000 vertices; the file holds 3 (and the one face).
      {"ascii.ply", ply_header("ascii", 1000, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "the header declares 1000 vertex element(s), which need at least 5999 bytes, but the file holds only 26 bytes"},
      {"binary.ply", ply_header("binary_little_endian", 1000, 1) + three,
       "the header declares 1000 vertex element(s), which need at least 12000 bytes, but the file holds only 36 bytes"},
      // 2e9 vertices would be 24 GB: refused before anything is allocated.
      {"huge.ply", ply_header("binary_little_endian", 2000000000, 1) + three,
       "the header declares 2000000000 vertex element(s), which need at least 24000000000 bytes"},
      // A face list longer than the rest of the file.
      {"longlist.ply", ply_header("binary_little_endian", 3, 1) + three + std::string("\xff\0\0\0\0", 5),
       "the file ends in face 0 of the 1 its header declares"},
      // Honest about its size, but a quad points past the vertices.
      {"badquad.ply", ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 900000000\n",
       "index 900000000 (entry 5) is out of range: there are 3 vertices"},
      {"noface.ply", ply_header("ascii", 3, 0) + "0 0 0\n1 0 0\n0 1 0\n", "contains no triangles or quads"},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.content);
    std::string message = build_error(in_world(fmt::format("Shape \"plymesh\" \"string filename\" \"{}\"\n", c.name)),
                                      {}, dir.path().string());
    EXPECT_NE(message.find("hostile.pbrt:8:17: error: parameter \"filename\""), std::string::npos)
        << c.name << ": " << message;
    EXPECT_NE(message.find(dir.file(c.name)), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
  }
}

// Measured-BRDF tensor files (.bsdf) cut short, of another format, or emptied.
TEST(HostileInput, MeasuredBsdfThatIsBroken) {
  TempDir dir("eyetrace-hostile");
  const std::string good = read_text(EYETRACE_SOURCE_DIR "/tests/data/measured/ggx-schlick.bsdf");
  ASSERT_GT(good.size(), 100000u);
  struct Case {
    const char* name;
    std::string content;
    const char* message;
  };
  const Case cases[] = {
      {"half.bsdf", good.substr(0, good.size() / 2), "truncated: field \"spectra\""},
      {"header.bsdf", good.substr(0, 30), "truncated: field 0's name needs 11 bytes at offset 20, the file has 30"},
      {"empty.bsdf", "", "truncated: the header \"tensor_file\" needs 12 bytes"},
      {"text.bsdf", "this is not a tensor file at all\n", "not a tensor file"},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.content);
    std::string message = build_error(
        in_world(fmt::format("Material \"measured\" \"string filename\" \"{}\"\nShape \"sphere\"\n", c.name)), {},
        dir.path().string());
    EXPECT_NE(message.find("hostile.pbrt:8:21: error: parameter \"filename\""), std::string::npos)
        << c.name << ": " << message;
    EXPECT_NE(message.find(dir.file(c.name)), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
  }
}

TEST(HostileInput, TextureThatIsNotAnImage) {
  TempDir dir("eyetrace-hostile");
  write_file(dir.file("text.png"), "this is not a PNG file\n");
  write_file(dir.file("empty.exr"), "");
  // A real PNG cut after its header.
  std::string png = read_text(EYETRACE_SOURCE_DIR "/scenes/textures/chart-uniform.png");
  ASSERT_GT(png.size(), 200u);
  write_file(dir.file("truncated.png"), png.substr(0, 100));
  for (const char* name : {"text.png", "empty.exr", "truncated.png"}) {
    std::string world = fmt::format(
        "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"{}\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"t\"\nShape \"sphere\"\n",
        name);
    std::string message = build_error(in_world(world), {}, dir.path().string());
    EXPECT_NE(message.find("hostile.pbrt:8:35: error: parameter \"filename\""), std::string::npos)
        << name << ": " << message;
    EXPECT_NE(message.find(name), std::string::npos) << name << ": " << message;
  }
}

// ---------------------------------------------------------------------------------------
// Film, sampler and eye limits

TEST(HostileInput, ResolutionsAndSamplesPerPixel) {
  auto film = [](const std::string& xy) {
    return fmt::format("Film \"rgb\" {} \"string filename\" \"out.exr\"\nWorldBegin\n", xy);
  };
  EXPECT_ERROR(film("\"integer xresolution\" 0"),
               "hostile.pbrt:1:12: error: parameter \"xresolution\": 0 pixels is outside [1, 32768] pixels");
  EXPECT_ERROR(film("\"integer xresolution\" 1000000 \"integer yresolution\" 1000000"),
               "parameter \"xresolution\": 1000000 pixels is outside [1, 32768] pixels");
  EXPECT_ERROR(film("\"integer xresolution\" 8 \"integer yresolution\" -8"),
               "parameter \"yresolution\": -8 pixels is outside [1, 32768] pixels");
  RenderOverrides huge;
  huge.resolution = IVec2(32768, 32768);
  huge.max_memory_bytes = uint64_t(1) << 30;
  EXPECT_PRED_FORMAT2(contains, build_error(in_world(""), huge),
                      "error: a 32768x32768 film needs about 44.0 GiB, more than the limit of 1.0 GiB (--max-memory)");
  RenderOverrides zero;
  zero.resolution = IVec2(0, 0);
  EXPECT_PRED_FORMAT2(contains, build_error(in_world(""), zero), "--resolution 0x0 is outside 1..32768 per side");
  EXPECT_EQ(build_error(film("\"integer xresolution\" 1 \"integer yresolution\" 1")), "");

  auto sampler = [](const std::string& spp) {
    return fmt::format("Sampler \"zsobol\" \"integer pixelsamples\" {}\nWorldBegin\n", spp);
  };
  EXPECT_ERROR(sampler("0"), "hostile.pbrt:1:18: error: parameter \"pixelsamples\": 0 is outside [1, 16777216]");
  EXPECT_ERROR(
      sampler("1099511627776"),  // 2^40
      "hostile.pbrt:1:41: error: parameter \"integer pixelsamples\": value 1099511627776 is not a 32-bit integer");
  EXPECT_ERROR(sampler("-5"), "parameter \"pixelsamples\": -5 is outside [1, 16777216]");
  EXPECT_ERROR(
      std::string("Sampler \"stratified\" \"integer xsamples\" 100000 \"integer ysamples\" 100000\nWorldBegin\n"),
      "parameter \"xsamples\": xsamples x ysamples = 10000000000 is more than 16777216");
  RenderOverrides too_many;
  too_many.spp = 1 << 30;
  EXPECT_PRED_FORMAT2(contains, build_error(in_world(""), too_many),
                      "error: --spp 1073741824 is more than the 16777216 samples per pixel a sampler supports");
}

std::string eye_error(const std::string& camera) {
  RenderOverrides o;
  try {
    o.camera = parse_directive_text(camera, "Camera", "--camera");
  } catch (const SceneError& e) {
    return e.what();
  }
  return build_error(in_world(""), o);
}

TEST(HostileInput, EyePupilsAndAccommodation) {
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"navarro\" \"float pupildiameter\" 0"),
                      "--camera:1:18: error: parameter \"pupildiameter\": 0 mm is outside (0, 10] mm");
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"navarro\" \"float pupildiameter\" 20"),
                      "parameter \"pupildiameter\": 20 mm is outside (0, 10] mm");
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"navarro\" \"float accommodation\" -1"),
                      "parameter \"accommodation\": -1 D is outside the range of model 'navarro' [0, 15] D");
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"navarro\" \"float accommodation\" 1000"),
                      "1000 D is outside the range of model 'navarro' [0, 15] D");
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"gullstrand\" \"float accommodation\" 1000"),
                      "parameter \"accommodation\"");
  EXPECT_PRED_FORMAT2(contains, eye_error("Camera \"navarro\" \"float pupildiameter\" nan"),
                      "--camera:1:40: error: parameter \"float pupildiameter\": \"nan\" is not a finite number");
  // Tiny but positive pupils are valid: the image is dark, never NaN.
  EXPECT_EQ(eye_error("Camera \"navarro\" \"float pupildiameter\" 1e-6"), "");
}

// The spectral film's buckets: zero, too many, an empty or out-of-range band, a non-EXR output.
TEST(HostileInput, SpectralFilmBucketsAndOutput) {
  auto film = [](const std::string& params) {
    return fmt::format("Film \"spectral\" {} \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n",
                       params);
  };
  EXPECT_ERROR(film("\"integer nbuckets\" 0"),
               "hostile.pbrt:1:17: error: parameter \"nbuckets\": 0 is outside [1, 512]");
  EXPECT_ERROR(film("\"integer nbuckets\" 100000"),
               "hostile.pbrt:1:17: error: parameter \"nbuckets\": 100000 is outside [1, 512]");
  EXPECT_ERROR(film("\"integer nbuckets\" -3"), "parameter \"nbuckets\": -3 is outside [1, 512]");
  EXPECT_ERROR(film("\"float nbuckets\" 16"), "hostile.pbrt:1:17: error: parameter \"nbuckets\" has type \"float\"");
  EXPECT_ERROR(film("\"integer nbuckets\" [16 32]"), "parameter \"nbuckets\" takes one value, got 2");
  EXPECT_ERROR(film("\"float lambdamin\" 700 \"float lambdamax\" 400"),
               "hostile.pbrt:1:39: error: parameter \"lambdamax\": lambdamin 700 nm must be below lambdamax 400 nm");
  EXPECT_ERROR(film("\"float lambdamax\" 400"), "parameter \"lambdamax\": lambdamin 400 nm must be below lambdamax");
  EXPECT_ERROR(film("\"float lambdamin\" 300"), "parameter \"lambdamin\": 300 nm is outside [360, 830] nm");
  EXPECT_ERROR(film("\"float lambdamax\" 1000"), "parameter \"lambdamax\": 1000 nm is outside [360, 830] nm");
  EXPECT_ERROR(film("\"float lambdamin\" nan"), "parameter \"float lambdamin\": \"nan\" is not a finite number");
  EXPECT_ERROR(film("\"string filename\" \"out.png\""),
               "hostile.pbrt:1:17: error: parameter \"filename\": \"out.png\": the spectral film writes EXR only");
  RenderOverrides png;
  png.output = "cli.png";
  EXPECT_PRED_FORMAT2(
      contains, build_error(film(""), png),
      "--output \"cli.png\": the spectral film (Film \"spectral\" at hostile.pbrt:1:1) writes EXR only");
  RenderOverrides exr;  // the command line's .exr replaces the scene's .png
  exr.output = "cli.exr";
  EXPECT_EQ(build_error(film("\"string filename\" \"out.png\""), exr), "");
  // Bucket parameters belong to the spectral film only.
  EXPECT_ERROR(std::string("Film \"rgb\" \"integer nbuckets\" 16\nWorldBegin\n"),
               "hostile.pbrt:1:12: error: Film \"rgb\": unused parameter \"integer nbuckets\"");
  // The buckets count towards the memory limit: 12 bytes each per pixel (a double and a float).
  RenderOverrides big;
  big.resolution = IVec2(4096, 4096);
  big.max_memory_bytes = uint64_t(16) << 30;
  EXPECT_PRED_FORMAT2(contains, build_error(film("\"integer nbuckets\" 512"), big),
                      "a 4096x4096 film needs about 96.7 GiB, more than the limit of 16.0 GiB (--max-memory)");
  big.resolution = IVec2(512, 512);
  big.max_memory_bytes = uint64_t(1) << 30;
  EXPECT_EQ(build_error(film("\"integer nbuckets\" 128"), big), "");  // 0.39 GiB
  EXPECT_PRED_FORMAT2(contains, build_error(film("\"integer nbuckets\" 512"), big),
                      "a 512x512 film needs about 1.5 GiB, more than the limit of 1.0 GiB (--max-memory)");
  EXPECT_EQ(build_error(film("\"integer nbuckets\" 1 \"float lambdamin\" 360 \"float lambdamax\" 830")), "");
}

// A spectral render of a scene whose spectra are zero, huge or tiny at some wavelengths (after
// the luminance normalisation of lights, the area light reaches ~1e36 at 830 nm): every pixel
// of every channel is finite (a sample whose estimate overflows is discarded and counted).
TEST(HostileInput, SpectralFilmOfExtremeSpectraHasNoNaN) {
  const std::string text = R"(LookAt 0 0 -5  0 0 0  0 1 0
Camera "perspective" "float fov" 45
Film "spectral" "integer xresolution" 8 "integer yresolution" 8 "integer nbuckets" 47 "float lambdamin" 360 "float lambdamax" 830
Sampler "independent" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 5
PixelFilter "gaussian"
WorldBegin
LightSource "infinite" "spectrum L" [360 0  500 0  501 1e30  502 0  830 0]
AttributeBegin
AreaLightSource "diffuse" "spectrum L" [360 1e-30  829 1e-30  830 1e6]
Shape "sphere" "float radius" 0.5
AttributeEnd
Material "dielectric" "spectrum eta" "glass-BK7"
Translate 1 0 0
Shape "sphere" "float radius" 0.7
Material "diffuse" "spectrum reflectance" [360 0  600 1  830 0]
Translate -2 0 0
Shape "sphere" "float radius" 0.7
)";
  RenderResult r = render(text);
  EXPECT_EQ(r.nonfinite_pixels, 0);
  EXPECT_LT(r.nonfinite_samples, 8u * 8u * 16u / 10u);
}

// ---------------------------------------------------------------------------------------
// The program: exit codes, messages and output files

using test::run_eyetrace;
using test::RunResult;
using test::shell_quote;

// Runs several command lines at once: most of a run is the program loading its libraries.
std::vector<RunResult> run_eyetrace_all(const std::vector<std::string>& args) {
  std::vector<std::future<RunResult>> runs;
  for (const std::string& a : args) runs.push_back(std::async(std::launch::async, [a] { return run_eyetrace(a); }));
  std::vector<RunResult> results;
  for (auto& r : runs) results.push_back(r.get());
  return results;
}

// A valid 8x8 scene in `dir`, returned as its path.
std::string write_scene(const TempDir& dir, const std::string& name = "scene.pbrt") {
  std::string path = dir.file(name);
  write_file(path, in_world("LightSource \"distant\"\nShape \"sphere\"\n"));
  return path;
}

// A refused run names the problem, writes no output, and exits with the documented status:
// 2 for a bad command line (CLI11 rejects the value; its own codes 105, 106... are not
// used), 1 for an error in the scene or in text read as scene text (--camera).
TEST(HostileProgram, RefusedRunsExitNonZeroNamingTheProblem) {
  TempDir dir("eyetrace-hostile");
  std::string truncated = dir.file("truncated.pbrt");
  write_file(truncated, in_world("Shape \"trianglemesh\" \"point3 P\" [ 0 0 0"));
  write_file(dir.file("blocker"), "a regular file where a directory should be");
  std::string out = " -o " + shell_quote(dir.file("out.exr"));
  std::string base = "render -q " + shell_quote(write_scene(dir)) + out;
  struct Case {
    std::string args;
    std::string message;
    int exit_code;
  };
  const std::vector<Case> cases = {
      {base + " --camera " + shell_quote("Camera \"navarro\" \"float pupildiameter\" 20"),
       "--camera:1:18: error: parameter \"pupildiameter\": 20 mm is outside (0, 10] mm", 1},
      {base + " --camera " + shell_quote("Camera \"navarro\" \"float accommodation\" 1000"),
       "--camera:1:18: error: parameter \"accommodation\": 1000 D is outside the range of model 'navarro' [0, 15] D",
       1},
      {"render -q " + shell_quote(truncated) + out,
       "truncated.pbrt:8:33: error: parameter \"point3 P\": '[' has no matching ']' before the end of the file", 1},
      {base + " --spp 0", "--spp: Value 0 not in range 1 to 16777216", 2},
      {base + " --spp 1099511627776", "--spp", 2},
      {base + " --spp many", "--spp: Value many", 2},
      {base + " --threads 0", "--threads: Value 0 not in range", 2},
      {base + " --no-such-option", "The following argument was not expected: --no-such-option", 2},
      {base + " --resolution 0x0", "--resolution: \"0x0\": expected WxH with 1 <= W, H <= 32768", 2},
      {base + " --resolution 1000000x1000000", "--resolution: \"1000000x1000000\": expected WxH", 2},
      {base + " --crop 0.5,0.2,0,1", "--crop: \"0.5,0.2,0,1\": needs 0 <= x0 < x1 <= 1", 2},
      {base + " --checkpoint -1", "--checkpoint: Value -1 not in range", 2},
      {"render -q " + shell_quote(write_scene(dir)) + " -o " + shell_quote(dir.file("out.bmp")),
       "--output: \"" + dir.file("out.bmp") + "\": the extension must be .exr (linear float) or .png (sRGB 8-bit)", 2},
      {"render -q " + shell_quote(write_scene(dir)) + " -o " + shell_quote(dir.file("blocker/out.png")),
       "blocker/out.png", 1},
  };
  std::vector<std::string> args;
  for (const Case& c : cases) args.push_back(c.args);
  std::vector<RunResult> results = run_eyetrace_all(args);
  for (size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(results[i].status, cases[i].exit_code) << cases[i].args << "\n" << results[i].output;
    EXPECT_NE(results[i].output.find(cases[i].message), std::string::npos) << cases[i].args << "\n"
                                                                           << results[i].output;
  }
  EXPECT_FALSE(fs::exists(dir.file("out.exr")));
  EXPECT_FALSE(fs::exists(dir.file("out.bmp")));
}

// A missing output directory is created (documented in docs/robustness.md).
TEST(HostileProgram, MissingOutputDirectoryIsCreated) {
  TempDir dir("eyetrace-hostile");
  RunResult r =
      run_eyetrace("render -q " + shell_quote(write_scene(dir)) + " -o " + shell_quote(dir.file("new/sub/out.png")));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir.file("new/sub/out.png")));
}

TEST(HostileProgram, ExistingOutputSurvivesFailedRuns) {
  TempDir dir("eyetrace-hostile");
  std::string scene = write_scene(dir);
  std::string output = dir.file("out.exr");
  const std::string precious = "finished work from yesterday\n";
  write_file(output, precious);
  std::string bad_scene = dir.file("bad.pbrt");
  write_file(bad_scene, in_world("Shape \"sphere\" \"float radius\" -1\n"));
  const std::string runs[] = {
      "render -q " + shell_quote(bad_scene) + " -o " + shell_quote(output),
      "render -q " + shell_quote(scene) + " -o " + shell_quote(output) + " --camera " +
          shell_quote("Camera \"navarro\" \"float pupildiameter\" 20"),
      "render -q " + shell_quote(scene) + " -o " + shell_quote(output) + " --resolution 0x0",
      "render -q " + shell_quote(dir.file("missing.pbrt")) + " -o " + shell_quote(output),
  };
  const int exit_codes[] = {1, 1, 2, 1};  // 2: a bad command line
  std::vector<RunResult> results = run_eyetrace_all(std::vector<std::string>(std::begin(runs), std::end(runs)));
  for (size_t i = 0; i < results.size(); ++i)
    EXPECT_EQ(results[i].status, exit_codes[i]) << runs[i] << "\n" << results[i].output;
  EXPECT_EQ(read_text(output), precious);
  // Nothing else (no temporary file) is left behind.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 3);  // scene.pbrt, bad.pbrt, out.exr
}

// --- The spectral film through the program --------------------------------------------

// The Cornell box with its Film line replaced by a spectral film of `buckets` buckets.
std::string write_spectral_cornell(const TempDir& dir, int buckets) {
  std::string text = read_text(EYETRACE_SOURCE_DIR "/scenes/cornell-box.pbrt");
  const size_t at = text.find("Film \"rgb\"");
  EXPECT_NE(at, std::string::npos);
  text.replace(at, text.find('\n', at) - at,
               fmt::format("Film \"spectral\" \"integer nbuckets\" {} \"string filename\" \"out.exr\"", buckets));
  const std::string path = dir.file(fmt::format("spectral{}.pbrt", buckets));
  write_file(path, text);
  return path;
}

// A spectral render stopped by SIGINT after its first checkpoint resumes to the uninterrupted
// render's image, every bucket bit for bit; a state is refused by a film of another bucket
// count (and kept); a PNG output is refused.
TEST(HostileProgram, SpectralFilmCheckpointsResumeExactlyAndRefuseMismatches) {
  TempDir dir("eyetrace-hostile");
  const std::string scene16 = write_spectral_cornell(dir, 16), scene8 = write_spectral_cornell(dir, 8);
  const std::string out = dir.file("out.exr"), ref = dir.file("ref.exr");
  auto args = [&](const std::string& scene, const std::string& output, const std::string& threads) {
    return std::vector<std::string>{"render", scene, "--resolution", "32x32", "--spp", "256", "--threads", threads,
                                    "--seed", "7",   "-q",           "-o",    output};
  };
  std::vector<std::string> first = args(scene16, out, "1");
  for (const char* a : {"--checkpoint", "0", "--pass-samples", "8"}) first.push_back(a);
  // 130 is the program's own exit after the signal (being killed by it would be 1000 + 2).
  EXPECT_EQ(test::run_eyetrace_and_signal(first, dir.file("first.log"), out + ".state", SIGINT), 130)
      << read_text(dir.file("first.log"));
  ASSERT_TRUE(fs::exists(out + ".state"));
  EXPECT_EQ(read_image_attribute(out, "eyetrace:interrupted"), "1");
  const Image partial = read_image(out);
  EXPECT_EQ(partial.channels, 19);
  for (float v : partial.pixels) EXPECT_TRUE(std::isfinite(v));

  const std::string state = read_text(out + ".state");
  RunResult refused = run_eyetrace("render " + shell_quote(scene8) + " --resolution 32x32 --spp 256 --seed 7 -q -o " +
                                   shell_quote(out) + " --resume");
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("is for a film with 16 spectral buckets, this render's has 8"), std::string::npos)
      << refused.output;
  EXPECT_EQ(read_text(out + ".state"), state) << "a refused resume must not touch the state";

  std::vector<std::string> resume = args(scene16, out, "2");
  resume.push_back("--resume");
  EXPECT_EQ(test::run_eyetrace_logged(resume, dir.file("resume.log")), 0) << read_text(dir.file("resume.log"));
  EXPECT_EQ(test::run_eyetrace_logged(args(scene16, ref, "2"), dir.file("ref.log")), 0)
      << read_text(dir.file("ref.log"));
  EXPECT_FALSE(fs::exists(out + ".state"));
  const Image a = read_image(out), b = read_image(ref);
  ASSERT_EQ(a.channels, 19);
  EXPECT_EQ(a.channel_names, b.channel_names);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);

  RunResult png = run_eyetrace("render -q " + shell_quote(scene16) + " -o " + shell_quote(dir.file("out.png")));
  EXPECT_EQ(png.status, 1) << png.output;
  EXPECT_NE(png.output.find("--output \"" + dir.file("out.png") + "\": the spectral film (Film \"spectral\" at "),
            std::string::npos)
      << png.output;
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
