// NamedMaterial before the MakeNamedMaterial it names. pbrt-v4 records only the name
// (BasicSceneBuilder::NamedMaterial) and looks it up when the shapes are made, after the whole
// scene is read: checked with pbrt-v4 (5f7a606), a sphere under `NamedMaterial "m"` followed by
// `MakeNamedMaterial "m"` renders; an undefined name is an error at the shape that uses it
// ("und.pbrt:8:0: nope: no named material defined."), and none when no shape uses it. The
// collection's contemporary-bathroom.pbrt names its light materials before including
// materials.pbrt.
#include <gtest/gtest.h>

#include <string>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::channel_mean;
using test::image_mean;
using test::render_text;

const std::string kHead =
    "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
    "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
    "Sampler \"independent\" \"integer pixelsamples\" 4\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n";
const std::string kDefine = "MakeNamedMaterial \"m\" \"string type\" \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n";

std::string error_of(const std::string& text) {
  try {
    render_text(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// The same scene with the definition after its use renders the same image, pixel for pixel.
TEST(NamedMaterial, MayComeBeforeItsDefinition) {
  const Image before = render_text(kHead + kDefine + "NamedMaterial \"m\"\nShape \"sphere\"\n");
  const Image after = render_text(kHead + "NamedMaterial \"m\"\nShape \"sphere\"\n" + kDefine);
  ASSERT_GT(image_mean(before), 0.0);
  EXPECT_EQ(image_mean(after), image_mean(before));
  EXPECT_EQ(channel_mean(after, 1), channel_mean(before, 1));
}

TEST(NamedMaterial, UndefinedNameIsAnErrorAtTheShapeThatUsesIt) {
  const std::string e = error_of(kHead + kDefine + "NamedMaterial \"n\"\nShape \"sphere\"\n");
  EXPECT_NE(e.find("test.pbrt:9:1"), std::string::npos) << e;
  EXPECT_NE(e.find("NamedMaterial \"n\" is not defined with MakeNamedMaterial (did you mean \"m\"?)"),
            std::string::npos)
      << e;
}

TEST(NamedMaterial, UndefinedNameThatNoShapeUsesIsNoError) {
  EXPECT_EQ(error_of(kHead + "NamedMaterial \"n\"\nLightSource \"point\"\n"), "");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
