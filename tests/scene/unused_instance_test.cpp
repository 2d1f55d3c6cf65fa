// An ObjectBegin that no ObjectInstance names cannot be reached by any ray: the builder skips
// its shapes and BVH (issue 5, "no BVH build for geometry no ray can reach") and says so once.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/error.h"
#include "render/scene.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// The object's sphere has a negative radius, an error whenever the sphere is built: building
// succeeds only if the object really is skipped.
std::string scene(const std::string& instance_line) {
  return "Film \"rgb\" \"integer xresolution\" 4 \"integer yresolution\" 4\nWorldBegin\n"
         "Shape \"sphere\" \"float radius\" 1\n"
         "ObjectBegin \"broken\"\nShape \"sphere\" \"float radius\" -1\nObjectEnd\n" +
         instance_line;
}

TEST(UnusedInstance, IsNotBuiltAndIsReported) {
  const int before = warning_count();
  RenderSetup s = build_render_setup(parse_scene_string(scene(""), "unused.pbrt", "."), {});
  EXPECT_EQ(warning_count() - before, 1);
  EXPECT_EQ(s.scene->primitive_count(), 1u);  // the one sphere outside the object
}

TEST(UnusedInstance, SameObjectInstancedIsBuilt) {
  SceneDescription desc = parse_scene_string(scene("ObjectInstance \"broken\"\n"), "used.pbrt", ".");
  try {
    build_render_setup(desc, {});
    FAIL() << "the instanced object's negative radius was not reported";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("used.pbrt:5:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
