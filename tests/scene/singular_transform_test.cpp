// A ConcatTransform or Transform that is singular (an exporter's all-zero row, as some of
// pbrt-v4-scenes have): the shapes and instances under it are dropped, each with a warning
// naming its file:line and the directive's; the rest of the scene is untouched, and a light
// under it is an error (it has no place to be).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/unity_id.h"
#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const char* kZeroRow = "[ 1 0 0 0  0 1 0 0  0 0 0 0  0 0 0 1 ]";

TEST(SingularTransform, ShapesUnderItAreDroppedWithAWarning) {
  WarningCollector warnings;
  const std::string text = std::string("WorldBegin\nShape \"sphere\"\nAttributeBegin\nConcatTransform ") + kZeroRow +
                           "\nTranslate 1 2 3\nShape \"disk\"\nShape \"sphere\"\nAttributeEnd\nShape \"disk\"\n";
  SceneDescription d = parse_scene_string(text, "s.pbrt", ".");
  ASSERT_EQ(d.shapes.size(), 2u);  // lines 2 and 9: AttributeEnd restored the transform
  EXPECT_EQ(d.shapes[0].loc.line, 2);
  EXPECT_EQ(d.shapes[1].loc.line, 9);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(d.shapes[1].world_from_object.inverse_matrix()[c][r]));
  const std::vector<Diagnostic> w = warnings.warnings();
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].to_string(),
            "s.pbrt:6:1: warning: Shape \"disk\" dropped: the transform made singular at s.pbrt:4:1 maps it to "
            "something flat, without a normal");
  EXPECT_EQ(w[1].loc.line, 7);
}

// A replacing transform (Transform, Identity, CoordSysTransform) ends it; one that is
// singular starts it.
TEST(SingularTransform, ReplacedTransformEndsIt) {
  WarningCollector warnings;
  const std::string text = std::string("WorldBegin\nTransform ") + kZeroRow +
                           "\nShape \"sphere\"\nIdentity\nShape \"disk\"\nConcatTransform " + kZeroRow +
                           "\nObjectBegin \"o\"\nObjectEnd\nObjectInstance \"o\"\nCoordSysTransform \"world\"\n"
                           "ObjectInstance \"o\"\n";
  SceneDescription d = parse_scene_string(text, "r.pbrt", ".");
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(d.shapes[0].name, "disk");
  ASSERT_EQ(d.instance_uses.size(), 1u);
  EXPECT_EQ(d.instance_uses[0].loc.line, 11);
  const std::vector<Diagnostic> w = warnings.warnings();
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].loc.line, 3);
  EXPECT_EQ(w[1].to_string(),
            "r.pbrt:9:1: warning: ObjectInstance \"o\" dropped: the transform made singular at r.pbrt:6:1 maps it to "
            "something flat, without a normal");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
