// The pbrt-v4 parser on malformed input: every error is a SceneError whose message names
// file:line:col (hand-counted below) and what is wrong; truncated files never crash or hang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

const fs::path kDataDir = fs::path(EYETRACE_SOURCE_DIR) / "tests" / "data" / "parser";

// The message of the SceneError `f` throws ("" and a test failure if it throws none).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SceneError";
  return "";
}

std::string parse_error(const std::string& text) {
  return error_of([&] { parse_scene_string(text, "test.pbrt", kDataDir.string()); });
}

struct BadCase {
  const char* what;
  std::string text;
  std::vector<std::string> expected;  // substrings of the message, in any order
};

void expect_errors(const std::vector<BadCase>& cases) {
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    std::string message = parse_error(c.text);
    for (const auto& e : c.expected) EXPECT_NE(message.find(e), std::string::npos) << message << "\n  lacks: " << e;
  }
}

using test::read_text;

TEST(ParserErrors, Syntax) {
  expect_errors({
      {"unknown directive",
       "WorldBegin\nShpae \"sphere\"\n",
       {"test.pbrt:2:1: error: unknown directive \"Shpae\" (did you mean \"Shape\"?)"}},
      {"stray ]", "WorldBegin\nShape \"sphere\" ]\n", {"test.pbrt:2:16: error: unexpected ']'"}},
      {"values without brackets",
       "WorldBegin\nShape \"sphere\" \"float radius\" 1 2\n",
       {"test.pbrt:2:33: error: unexpected number 2", "[ ]"}},
      {"string where a directive belongs",
       "WorldBegin\n\"sphere\"\n",
       {"test.pbrt:2:1: error: unexpected string \"sphere\""}},
      {"unterminated string", "WorldBegin\nShape \"sphere\n", {"test.pbrt:2:7: error: unterminated string \"sphere\""}},
      {"unterminated string at end of file",
       "WorldBegin\nShape \"sph",
       {"test.pbrt:2:7: error: unterminated string", "end of file"}},
      {"unknown escape", "WorldBegin\nShape \"a\\qb\"\n", {"test.pbrt:2:9: error: unknown escape sequence \"\\q\""}},
      {"unbalanced [",
       "WorldBegin\nShape \"sphere\" \"float radius\" [ 1",
       {"test.pbrt:2:31: error: parameter \"float radius\": '[' has no matching ']'"}},
      {"missing ] before a directive",
       "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\nShape \"disk\"\n",
       {"test.pbrt:3:1: error: parameter \"float radius\": expected a number, got \"Shape\"", "'[' at 2:31"}},
      {"nested [",
       "WorldBegin\nShape \"sphere\" \"float radius\" [ [ 1 ] ]\n",
       {"test.pbrt:2:33: error: parameter \"float radius\": unexpected '['"}},
      {"UTF-16 file", std::string("\xff\xfeW\0o", 5), {"test.pbrt:1:1: error: file is UTF-16 encoded"}},
  });
}

TEST(ParserErrors, ParameterValues) {
  const std::string w = "WorldBegin\nShape \"sphere\" ";
  expect_errors({
      {"string for float",
       w + "\"float radius\" \"big\"",
       {"test.pbrt:2:31: error: parameter \"float radius\": expected a number, got string \"big\""}},
      {"unknown type",
       w + "\"flaot radius\" 1",
       {"test.pbrt:2:16: error: unknown parameter type \"flaot\" in \"flaot radius\" (did you mean \"float\"?)"}},
      {"malformed declaration",
       w + "\"radius\" 1",
       {"test.pbrt:2:16: error: malformed parameter declaration \"radius\": expected \"type name\""}},
      {"three words", w + "\"float radius extra\" 1", {"test.pbrt:2:16", "malformed parameter declaration"}},
      {"1e400",
       w + "\"float radius\" 1e400",
       {"test.pbrt:2:31: error: parameter \"float radius\": value 1e400 is out of range"}},
      {"nan", w + "\"float radius\" nan", {"test.pbrt:2:31", "\"float radius\"", "\"nan\" is not a finite number"}},
      {"inf in an array",
       w + "\"float r\" [ 1 -inf ]",
       {"test.pbrt:2:30", "\"float r\"", "\"-inf\" is not a finite number"}},
      {"word for float", w + "\"float radius\" big", {"parameter \"float radius\": expected a number, got \"big\""}},
      {"bool for float", w + "\"float radius\" true", {"parameter \"float radius\": expected a number, got true"}},
      {"fractional integer",
       w + "\"integer n\" 1.5",
       {"test.pbrt:2:28", "parameter \"integer n\": value 1.5 is not a 32-bit integer"}},
      {"huge integer", w + "\"integer n\" 3e9", {"value 3e9 is not a 32-bit integer"}},
      {"number for bool", w + "\"bool b\" 1", {"parameter \"bool b\": expected true or false, got \"1\""}},
      {"bad quoted bool",
       w + "\"bool b\" \"yes\"",
       {"parameter \"bool b\": expected true or false, got string \"yes\""}},
      {"number for string", w + "\"string s\" 3", {"parameter \"string s\": expected a quoted string, got \"3\""}},
      {"number for texture", w + "\"texture t\" 3", {"parameter \"texture t\": expected a quoted string"}},
      {"empty array", w + "\"float radius\" [ ]", {"test.pbrt:2:16: error: parameter \"float radius\" has no values"}},
      {"incomplete point3",
       w + "\"point3 P\" [ 1 2 3 4 ]",
       {"parameter \"point3 P\" needs a multiple of 3 values, got 4"}},
      {"incomplete rgb", w + "\"rgb c\" 1", {"parameter \"rgb c\" needs a multiple of 3 values, got 1"}},
      {"odd spectrum pairs", w + "\"spectrum s\" [ 300 1 400 ]", {"(wavelength, value) pairs, got 3 values"}},
      {"mixed spectrum",
       w + "\"spectrum s\" [ 300 \"x\" ]",
       {"parameter \"spectrum s\": cannot mix numbers and a spectrum name"}},
      {"parameter repeated with another type",
       w + "\"float radius\" 1 \"integer radius\" 2",
       {"test.pbrt:2:33: error: parameter \"radius\" given twice (first at test.pbrt:2:16)"}},
      {"value missing at end of file",
       w + "\"float radius\"",
       {"parameter \"float radius\" has no value: end of file"}},
  });
}

TEST(ParserErrors, Directives) {
  expect_errors({
      {"unbalanced AttributeEnd",
       "WorldBegin\nAttributeEnd\n",
       {"test.pbrt:2:1: error: AttributeEnd without a matching AttributeBegin"}},
      {"unclosed AttributeBegin",
       "WorldBegin\nAttributeBegin\nShape \"sphere\"\n",
       {"test.pbrt:2:1: error: AttributeBegin has no matching AttributeEnd"}},
      {"unclosed ObjectBegin",
       "WorldBegin\nObjectBegin \"a\"\n",
       {"test.pbrt:2:1: error: ObjectBegin has no matching ObjectEnd"}},
      {"AttributeEnd closing ObjectBegin",
       "WorldBegin\nObjectBegin \"a\"\nAttributeEnd\n",
       {"test.pbrt:3:1: error: AttributeEnd does not match the ObjectBegin at test.pbrt:2:1"}},
      {"unbalanced TransformEnd",
       "TransformEnd\n",
       {"test.pbrt:1:1: error: TransformEnd without a matching TransformBegin"}},
      {"MakeNamedMaterial without type",
       "WorldBegin\nMakeNamedMaterial \"gold\" \"float roughness\" 0\n",
       {"test.pbrt:2:1: error: MakeNamedMaterial \"gold\": missing the \"string type\" parameter"}},
      {"named material redefined",
       "WorldBegin\nMakeNamedMaterial \"m\" \"string type\" \"diffuse\"\nMakeNamedMaterial \"m\" \"string type\" "
       "\"diffuse\"\n",
       {"test.pbrt:3:1: error: MakeNamedMaterial: material \"m\" is already defined at test.pbrt:2:1"}},
      {"texture value type",
       "WorldBegin\nTexture \"t\" \"color\" \"checkerboard\"\n",
       {"test.pbrt:2:13: error: Texture \"t\": value type \"color\" must be \"float\" or \"spectrum\""}},
      {"texture redefined",
       "WorldBegin\nTexture \"t\" \"float\" \"constant\"\nTexture \"t\" \"float\" \"constant\"\n",
       {"test.pbrt:3:1: error: Texture: float texture \"t\" is already defined at test.pbrt:2:1"}},
      {"ObjectInstance unknown",
       "WorldBegin\nObjectBegin \"tree\"\nObjectEnd\nObjectInstance \"tre\"\n",
       {"test.pbrt:4:1: error: ObjectInstance: no object named \"tre\"", "(did you mean \"tree\"?)"}},
      {"nested ObjectBegin",
       "WorldBegin\nObjectBegin \"a\"\nObjectBegin \"b\"\n",
       {"test.pbrt:3:1", "instances cannot nest"}},
      {"ObjectEnd alone",
       "WorldBegin\nObjectEnd\n",
       {"test.pbrt:2:1: error: ObjectEnd without a matching ObjectBegin"}},
      {"unknown coordinate system",
       "WorldBegin\nCoordSysTransform \"wrold\"\n",
       {"test.pbrt:2:1: error: CoordSysTransform: no coordinate system named \"wrold\" (did you mean \"world\"?)"}},
      {"option after WorldBegin",
       "WorldBegin\nCamera \"perspective\"\n",
       {"test.pbrt:2:1: error: Camera is not allowed after WorldBegin"}},
      {"WorldBegin twice",
       "WorldBegin\nWorldBegin\n",
       {"test.pbrt:2:1: error: WorldBegin is not allowed after WorldBegin"}},
      {"shape before WorldBegin",
       "Shape \"sphere\"\n",
       {"test.pbrt:1:1: error: Shape is only allowed after WorldBegin"}},
      {"no WorldBegin", "Camera \"perspective\"\n", {"test.pbrt: error: the scene ends before WorldBegin"}},
      {"unknown Attribute target",
       "WorldBegin\nAttribute \"shapes\" \"float radius\" 1\n",
       {"test.pbrt:2:11: error: Attribute: unknown target \"shapes\"", "(did you mean \"shape\"?)"}},
      {"bad ActiveTransform",
       "ActiveTransform Sometimes\n",
       {"test.pbrt:1:17: error: ActiveTransform: expected StartTime, EndTime or All"}},
      {"unknown color space",
       "ColorSpace \"srbg\"\n",
       {"test.pbrt:1:12: error: ColorSpace: unknown color space \"srbg\" (did you mean \"srgb\"?)"}},
      {"name not quoted",
       "WorldBegin\nShape sphere\n",
       {"test.pbrt:2:7: error: Shape: expected a quoted type name, got \"sphere\""}},
      {"Option without declaration", "Option 3\n", {"test.pbrt:1:8: error: Option: expected a quoted \"type name\""}},
  });
}

TEST(ParserErrors, TransformsMustStayFiniteAndInvertible) {
  expect_errors({
      {"zero scale",
       "WorldBegin\nScale 0 1 1\n",
       {"test.pbrt:2:1: error: Scale: a zero factor makes the transform singular"}},
      {"zero rotation axis",
       "Rotate 30 0 0 0\n",
       {"test.pbrt:1:1: error: Rotate: the rotation axis is the zero vector"}},
      {"LookAt at itself",
       "LookAt 1 1 1  1 1 1  0 1 0\n",
       {"test.pbrt:1:1: error: LookAt: eye and look points coincide"}},
      {"LookAt along up",
       "LookAt 0 0 0  0 2 0  0 1 0\n",
       {"test.pbrt:1:1: error: LookAt: up vector and viewing direction are parallel"}},
      {"light under a singular matrix (shapes are dropped, parser_test.cpp)",
       "WorldBegin\nTransform [ 1 0 0 0  0 1 0 0  0 0 0 0  0 0 0 1 ]\nLightSource \"point\"\n",
       {"test.pbrt:3:1: error: LightSource: the current transform is singular (made so at test.pbrt:2:1); only "
        "shapes may stand under it (they are dropped)"}},
      {"product overflows",
       "Scale 1e10 1 1\nScale 1e10 1 1\n",
       {"test.pbrt:2:1: error: Scale makes the current transform overflow: it scales lengths by up to 1e+20"}},
      {"number beyond float", "Translate 1e39 0 0\n", {"test.pbrt:1:11: error: Translate: value 1e39 is out of range"}},
      {"nan in transform", "Translate 0 nan 0\n", {"test.pbrt:1:13: error: Translate: \"nan\" is not a finite number"}},
      {"too few numbers", "LookAt 0 0 5 0 0", {"LookAt takes 9 numbers; got end of file after 5"}},
      {"matrix without ]",
       "Transform [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1 WorldBegin",
       {"test.pbrt:1:48: error: Transform: expected ']' after 16 numbers, got \"WorldBegin\""}},
  });
}

TEST(ParserErrors, IncludeProblemsNameTheIncludingFile) {
  std::string missing = error_of([] { parse_scene_file((kDataDir / "missing_include.pbrt").string()); });
  EXPECT_NE(missing.find("missing_include.pbrt:3:1: error: Include \"does/not/exist.pbrt\": file not found"),
            std::string::npos)
      << missing;

  std::string self = error_of([] { parse_scene_file((kDataDir / "self_include.pbrt").string()); });
  EXPECT_NE(self.find("self_include.pbrt:2:1: error: recursive Include"), std::string::npos) << self;

  std::string cycle = error_of([] { parse_scene_file((kDataDir / "recursive_a.pbrt").string()); });
  EXPECT_NE(cycle.find("recursive_b.pbrt:2:1: error: recursive Include"), std::string::npos) << cycle;
  EXPECT_NE(cycle.find("recursive_a.pbrt -> recursive_b.pbrt -> recursive_a.pbrt"), std::string::npos) << cycle;

  std::string absent = error_of([] { parse_scene_file((kDataDir / "no_such_scene.pbrt").string()); });
  EXPECT_NE(absent.find("cannot read scene file"), std::string::npos) << absent;
  EXPECT_NE(absent.find("no_such_scene.pbrt"), std::string::npos) << absent;
}

TEST(ParserErrors, IncludeDepthIsCapped) {
  // A chain of 70 distinct files, each including the next: not recursive, but too deep.
  fs::path dir = fs::temp_directory_path() / ("eyetrace_parser_depth_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (int i = 0; i < 70; ++i) {
    std::ofstream(dir / fmt::format("f{}.pbrt", i)) << fmt::format("Include \"f{}.pbrt\"\n", i + 1);
  }
  std::ofstream(dir / "f70.pbrt") << "WorldBegin\n";
  std::string message = error_of([&] { parse_scene_file((dir / "f0.pbrt").string()); });
  EXPECT_NE(message.find("f63.pbrt:1:1: error: Include nesting is deeper than 64 files"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(ParserErrors, DirectiveTextChecksKeywordAndEnd) {
  std::string wrong = error_of([] { parse_directive_text("Film \"rgb\"", "Camera", "--camera"); });
  EXPECT_NE(wrong.find("--camera:1:1: error: expected a Camera directive, got \"Film\""), std::string::npos) << wrong;
  std::string junk =
      error_of([] { parse_directive_text("Camera \"pinhole\" \"float fov\" 30 WorldBegin", "Camera", "--camera"); });
  EXPECT_NE(junk.find("--camera:1:33: error: Camera: unexpected \"WorldBegin\" after the parameters"),
            std::string::npos)
      << junk;
  std::string bad =
      error_of([] { parse_directive_text("Camera \"pinhole\" \"float fov\" \"wide\"", "Camera", "--camera"); });
  EXPECT_NE(bad.find("--camera:1:30: error: parameter \"float fov\""), std::string::npos) << bad;
}

// Cutting a valid file anywhere gives either a valid scene or one clear error naming the
// file; never a crash, a hang or another exception type.
TEST(ParserErrors, TruncatedFilesFailCleanly) {
  std::string text = read_text(kDataDir / "basic.pbrt");
  ASSERT_GT(text.size(), 500u);
  int errors = 0;
  for (size_t n = 0; n <= text.size(); ++n) {
    try {
      parse_scene_string(text.substr(0, n), "cut.pbrt", kDataDir.string());
    } catch (const SceneError& e) {
      ++errors;
      std::string m = e.what();
      ASSERT_EQ(m.rfind("cut.pbrt", 0), 0u) << "prefix " << n << ": " << m;
      ASSERT_NE(m.find("error: "), std::string::npos) << m;
    }
  }
  EXPECT_GT(errors, int(text.size()) / 2);

  auto cut_after = [&](const std::string& marker) {
    size_t at = text.find(marker);
    EXPECT_NE(at, std::string::npos) << marker;
    return parse_error(text.substr(0, at + marker.size()));
  };
  EXPECT_NE(cut_after("\"metal-Au").find("unterminated string \"metal-Au\""), std::string::npos);
  EXPECT_NE(cut_after("\"rgb tex1\" [ .1").find("'[' has no matching ']'"), std::string::npos);
  EXPECT_NE(cut_after("  NamedMaterial \"gold\"").find("AttributeBegin has no matching AttributeEnd"),
            std::string::npos);
  EXPECT_NE(cut_after("LookAt 0 0 5   0").find("LookAt takes 9 numbers; got end of file after 4"), std::string::npos);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
