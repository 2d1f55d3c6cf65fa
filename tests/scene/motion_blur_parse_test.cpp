// Motion blur in the parser, against pbrt-v4's BasicSceneBuilder (scene.cpp, 5f7a606):
// ActiveTransform picks which of the two transforms the transform directives change,
// TransformTimes (before WorldBegin only) gives their times, and a Shape, an ObjectInstance or
// the Camera under two different transforms is animated; lights keep the start transform with
// a warning, an animated area light is an error, each naming its file:line.
#include <gtest/gtest.h>

#include <string>

#include "../support/unity_id.h"
#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

SceneDescription parse(const std::string& text) { return parse_scene_string(text, "m.pbrt", "."); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SceneError";
  return "";
}

Vec3 origin_of(const Transform& t) { return t.point(Vec3(0.f)); }

TEST(MotionBlurParse, ActiveTransformChangesOnlyTheChosenTransform) {
  WarningCollector warnings;
  SceneDescription d = parse(R"(WorldBegin
ActiveTransform EndTime
Translate 1 0 0
ActiveTransform All
Shape "sphere"
ActiveTransform StartTime
Translate 1 0 0
ActiveTransform All
Shape "disk"
Translate 0 2 0
Shape "disk"
)");
  ASSERT_EQ(d.shapes.size(), 3u);
  // EndTime: the start transform stays the identity, the end one moves.
  EXPECT_TRUE(d.shapes[0].animated);
  EXPECT_EQ(origin_of(d.shapes[0].world_from_object), Vec3(0, 0, 0));
  EXPECT_EQ(origin_of(d.shapes[0].world_from_object_end), Vec3(1, 0, 0));
  // StartTime caught the start transform up: both equal again, nothing moves.
  EXPECT_FALSE(d.shapes[1].animated);
  EXPECT_EQ(origin_of(d.shapes[1].world_from_object), Vec3(1, 0, 0));
  EXPECT_EQ(origin_of(d.shapes[1].world_from_object_end), Vec3(1, 0, 0));
  // All: both.
  EXPECT_FALSE(d.shapes[2].animated);
  EXPECT_EQ(origin_of(d.shapes[2].world_from_object_end), Vec3(1, 2, 0));
  EXPECT_TRUE(warnings.warnings().empty());
  EXPECT_EQ(d.transform_start_time, 0.f);  // pbrt-v4's defaults
  EXPECT_EQ(d.transform_end_time, 1.f);
}

// pbrt-v4 checks neither order nor equality of the two times (AnimatedTransform then jumps
// from start to end just after the start time; core/animated_transform_test.cpp).
TEST(MotionBlurParse, TransformTimesAreKeptEvenReversed) {
  SceneDescription d = parse("TransformTimes 2.5 -1\nWorldBegin\n");
  EXPECT_EQ(d.transform_start_time, 2.5f);
  EXPECT_EQ(d.transform_end_time, -1.f);
  EXPECT_NE(error_of("WorldBegin\nTransformTimes 0 1\n")
                .find("m.pbrt:2:1: error: TransformTimes is not allowed after "
                      "WorldBegin"),
            std::string::npos);
}

TEST(MotionBlurParse, CameraAndObjectInstanceCarryBothTransforms) {
  SceneDescription d = parse(R"(TransformTimes 1 3
ActiveTransform EndTime
Translate 0 0 -4
ActiveTransform All
Camera "perspective"
WorldBegin
ObjectBegin "o"
Shape "sphere"
ObjectEnd
ActiveTransform StartTime
Rotate 90 0 0 1
ActiveTransform All
ObjectInstance "o"
)");
  EXPECT_EQ(d.transform_start_time, 1.f);
  EXPECT_TRUE(d.camera.animated);
  EXPECT_EQ(d.camera.transform_start_time, 1.f);
  EXPECT_EQ(d.camera.transform_end_time, 3.f);
  // camera_from_world translated the world by -4 in z: the camera sits at +4 at the end.
  EXPECT_EQ(origin_of(d.camera.world_from_camera), Vec3(0, 0, 0));
  EXPECT_EQ(origin_of(d.camera.world_from_camera_end), Vec3(0, 0, 4));
  ASSERT_EQ(d.instance_uses.size(), 1u);
  EXPECT_TRUE(d.instance_uses[0].animated());
  EXPECT_NEAR(d.instance_uses[0].world_from_instance->vector(Vec3(1, 0, 0)).y, 1.f, 1e-6f);
  EXPECT_EQ(d.instance_uses[0].end_transform().vector(Vec3(1, 0, 0)), Vec3(1, 0, 0));
}

// pbrt-v4 reads the times at the Camera directive: a TransformTimes after it changes the
// world's times, not the camera's.
TEST(MotionBlurParse, CameraKeepsTheTimesInEffectAtItsDirective) {
  SceneDescription d = parse(
      "ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\nCamera \"perspective\"\n"
      "TransformTimes 2 5\nWorldBegin\n");
  EXPECT_EQ(d.camera.transform_start_time, 0.f);
  EXPECT_EQ(d.camera.transform_end_time, 1.f);
  EXPECT_EQ(d.transform_start_time, 2.f);
  EXPECT_EQ(d.transform_end_time, 5.f);
}

TEST(MotionBlurParse, AnimatedLightKeepsTheStartTransformWithAWarning) {
  WarningCollector warnings;
  SceneDescription d = parse("WorldBegin\nActiveTransform EndTime\nTranslate 0 5 0\nLightSource \"point\"\n");
  ASSERT_EQ(d.lights.size(), 1u);
  EXPECT_EQ(origin_of(d.lights[0].world_from_object), Vec3(0, 0, 0));
  ASSERT_EQ(warnings.warnings().size(), 1u);
  EXPECT_EQ(warnings.warnings()[0].to_string(),
            "m.pbrt:4:1: warning: LightSource: an animated transform is not supported here (as in pbrt-v4); the "
            "start-time transform is used");
}

TEST(MotionBlurParse, AnimatedAreaLightIsAnErrorAtTheShape) {
  std::string e =
      error_of("WorldBegin\nAreaLightSource \"diffuse\"\nActiveTransform EndTime\nTranslate 0 5 0\nShape \"sphere\"\n");
  EXPECT_NE(e.find("m.pbrt:5:1: error: Shape \"sphere\": animated area lights are not supported"), std::string::npos)
      << e;
}

// A moving shape inside an object definition keeps both transforms (the builder places it at
// each use); its area light is dropped as for every shape in an object, before it could move.
TEST(MotionBlurParse, AnimatedShapeInsideAnObjectKeepsBothTransforms) {
  WarningCollector warnings;
  SceneDescription d = parse(
      "WorldBegin\nAreaLightSource \"diffuse\"\nObjectBegin \"o\"\nActiveTransform EndTime\nTranslate 1 0 0\n"
      "Shape \"sphere\"\nObjectEnd\n");
  const ShapeEntity& s = d.instances.at("o").shapes.at(0);
  EXPECT_TRUE(s.animated);
  EXPECT_EQ(s.area_light, -1);
  EXPECT_EQ(origin_of(s.world_from_object_end), Vec3(1, 0, 0));
  ASSERT_EQ(warnings.warnings().size(), 1u);  // the area light's, as for a still shape
  EXPECT_NE(warnings.warnings()[0].message.find("area lights"), std::string::npos);
}

TEST(MotionBlurParse, MirroringOnlyAtOneEndIsAnError) {
  std::string e = error_of("WorldBegin\nActiveTransform EndTime\nScale 1 1 -1\nShape \"sphere\"\n");
  EXPECT_NE(e.find("m.pbrt:4:1: error: Shape: the start and end transforms cannot be interpolated"), std::string::npos)
      << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
