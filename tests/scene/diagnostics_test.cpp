// Diagnostics are values: a scene with several independent mistakes reports every one (up to
// a limit, then says how many more), in file order with exact places, without follow-on
// errors; the parameter a diagnostic concerns is a field, not something to read from text.
#include <gtest/gtest.h>

#include <string>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::vector<Diagnostic> parse_errors(const std::string& text) {
  try {
    parse_scene_string(text, "d.pbrt", ".");
  } catch (const SceneError& e) {
    return e.diagnostics();
  }
  return {};
}

std::vector<Diagnostic> build_errors(const std::string& text) {
  try {
    build_render_setup(parse_scene_string(text, "d.pbrt", "."), RenderOverrides{});
  } catch (const SceneError& e) {
    return e.diagnostics();
  }
  return {};
}

void expect_at(const Diagnostic& d, int line, int column, const std::string& fragment) {
  EXPECT_EQ(d.loc.file, "d.pbrt");
  EXPECT_EQ(d.loc.line, line) << d.to_string();
  EXPECT_EQ(d.loc.column, column) << d.to_string();
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_NE(d.message.find(fragment), std::string::npos) << d.to_string();
}

TEST(Diagnostics, ParserReportsEveryIndependentError) {
  const std::vector<Diagnostic> e = parse_errors(
      "WorldBegin\n"
      "Shpae \"sphere\"\n"                     // line 2: unknown directive
      "Shape \"sphere\" \"flaot radius\" 2\n"  // line 3: unknown parameter type
      "Translate 1 2\n"                        // line 4: too few numbers
      "AttributeBegin\n"
      "Shape \"sphere\"\n"
      "AttributeEnd\n");
  ASSERT_EQ(e.size(), 3u);
  expect_at(e[0], 2, 1, "unknown directive \"Shpae\"");
  expect_at(e[1], 3, 16, "unknown parameter type \"flaot\"");
  expect_at(e[2], 5, 1, "Translate takes 3 numbers; got \"AttributeBegin\" after 2");
}

TEST(Diagnostics, BuilderReportsEveryIndependentError) {
  const std::vector<Diagnostic> e = build_errors(
      "Camera \"perspective\" \"float fov\" 200\n"  // line 1: out of range
      "WorldBegin\n"
      "Shape \"spere\"\n"                                              // line 3: unknown shape
      "LightSource \"point\" \"rgb I\" [1 1 1] \"float scael\" 2\n");  // line 4: unused parameter
  ASSERT_EQ(e.size(), 3u);
  expect_at(e[0], 1, 22, "parameter \"fov\"");
  EXPECT_EQ(e[0].parameter, "fov");
  expect_at(e[1], 3, 1, "unsupported shape \"spere\" (did you mean \"sphere\"?)");
  expect_at(e[2], 4, 37, "unused parameter \"float scael\" (did you mean \"scale\"?)");
  EXPECT_EQ(e[2].parameter, "scael");
}

TEST(Diagnostics, ManyErrorsAreCappedAndCounted) {
  std::string text = "WorldBegin\n";
  for (int i = 0; i < 100; ++i) text += "Bogus" + std::to_string(i) + "\n";
  const std::vector<Diagnostic> e = parse_errors(text);
  ASSERT_EQ(e.size(), DiagnosticList::kMaxErrors + 1);
  expect_at(e[0], 2, 1, "unknown directive \"Bogus0\"");
  expect_at(e[DiagnosticList::kMaxErrors - 1], 21, 1, "unknown directive \"Bogus19\"");
  EXPECT_EQ(e.back().message, "80 more errors not shown (at most 20 are listed)");
}

TEST(Diagnostics, NoFollowOnErrorsAfterTheTextIsCutShort) {
  // The unclosed bracket runs to the end of the file: the open AttributeBegin and the missing
  // WorldBegin follow from it and are not reported again.
  const std::vector<Diagnostic> e = parse_errors("WorldBegin\nAttributeBegin\nShape \"sphere\" \"float radius\" [1\n");
  ASSERT_EQ(e.size(), 1u) << e.back().to_string();
  EXPECT_NE(e[0].message.find("'[' has no matching ']'"), std::string::npos) << e[0].to_string();
  // A complete text still gets its end-of-scene checks, beside its other errors.
  const std::vector<Diagnostic> f = parse_errors("Bogus\nWorldBegin\nAttributeBegin\n");
  ASSERT_EQ(f.size(), 2u);
  EXPECT_NE(f[1].message.find("AttributeBegin has no matching AttributeEnd"), std::string::npos);
  const std::vector<Diagnostic> g = parse_errors("Bogus\n");
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NE(g[1].message.find("ends before WorldBegin"), std::string::npos);
}

TEST(Diagnostics, TextIsOneLinePerDiagnostic) {
  try {
    parse_scene_string("WorldBegin\nA\nB\n", "d.pbrt", ".");
    FAIL() << "expected errors";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "d.pbrt:2:1: error: unknown directive \"A\"\nd.pbrt:3:1: error: unknown directive \"B\"");
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
