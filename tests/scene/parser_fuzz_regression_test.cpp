// Inputs found by the scene-parser fuzzer (tests/fuzz, tools/fuzz), kept with the message they
// must produce. Each once crashed a build of the parser.
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string parse_error(const std::string& text) {
  try {
    parse_scene_string(text, "fuzz.pbrt", "/");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// A parameter declaration as the last token. With clang 14 the temporary SourceLoc of the
// switch case before this one was destroyed although never constructed (a miscompilation of
// fmt's consteval format check; cmake/fuzzing.cmake works around it): free() of a stack address.
TEST(ParserFuzzRegression, ParameterWithoutValueAtEndOfFile) {
  EXPECT_EQ(parse_error("Sampler \"a\" \"integer b\""),
            "fuzz.pbrt:1:24: error: parameter \"integer b\" has no value: end of file");
  // The fuzzer's original input (an escaped quote in the name, the newline before the end).
  EXPECT_EQ(parse_error("# Foun), n`ot in the top-termplete pbrt-filename\"\"blackbody  \"basic.exr\"\n"
                        "Sampler \"indep\\\"dent\" \"integer pixelsamplesk\"\n"),
            "fuzz.pbrt:3:1: error: parameter \"integer pixelsamplesk\" has no value: end of file");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
