// pbrt-v4's default integrator is "volpath"; eyetrace renders it with "path". A scene that asks
// for volpath by name is told so; a scene without an Integrator line is not warned about a
// choice it never made.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {

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

TEST(DefaultIntegrator, ExplicitVolpathWarns) { EXPECT_EQ(warnings_building("Integrator \"volpath\""), 1); }

}  // namespace
}  // namespace eyetrace
