// pbrt-v4's default integrator is "volpath". A scene without media is rendered by the "path"
// estimator under that name, with no warning whether or not the scene names it.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const char* kScene = R"(Film "rgb" "integer xresolution" 4 "integer yresolution" 4
%s
WorldBegin
Shape "sphere"
)";

int warnings_building(const std::string& integrator_line) {
  char text[512];
  std::snprintf(text, sizeof text, kScene, integrator_line.c_str());
  const int before = warning_count();
  SceneDescription desc = parse_scene_string(text, "default.pbrt", ".");
  RenderSetup s = build_render_setup(desc, {});
  EXPECT_NE(s.integrator->to_string().find("path integrator"), std::string::npos) << s.integrator->to_string();
  return warning_count() - before;
}

TEST(DefaultIntegrator, NoWarningWithoutAnIntegratorLine) { EXPECT_EQ(warnings_building(""), 0); }

TEST(DefaultIntegrator, ExplicitVolpathDoesNotWarn) { EXPECT_EQ(warnings_building("Integrator \"volpath\""), 0); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
