// The overrides of a render request (scene/render_request.h), shared by `eyetrace render` and the
// Python module: the option texts are read to the values they spell, malformed ones are errors
// naming the option, and the setup built with them has the overridden film, sampler and camera.
#include "scene/render_request.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const char* kScene =
    "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
    "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 6\n"
    "Sampler \"independent\" \"integer pixelsamples\" 4\nWorldBegin\n"
    "LightSource \"infinite\" \"rgb L\" [0.7 0.5 0.3]\n";

// The parameter a SceneError names (its first diagnostic's), "" when `f` does not throw one.
template <typename F>
std::string error_parameter(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.first().parameter;
  }
  return "";
}

TEST(RenderRequest, ParsesResolutionAndCrop) {
  EXPECT_EQ(parse_resolution("640x480"), IVec2(640, 480));
  EXPECT_EQ(parse_resolution("1X2"), IVec2(1, 2));
  EXPECT_EQ(parse_crop("0,0.5,0.25,1"), Vec4(0.f, 0.5f, 0.25f, 1.f));
  for (const char* bad : {"640by480", "0x10", "640x", "640x480x3", "32769x1", ""})
    EXPECT_EQ(error_parameter([&] { parse_resolution(bad); }), "--resolution") << bad;
  for (const char* bad : {"0,1,0", "0.5,0.5,0,1", "0,1,0,1.5", "-0.1,1,0,1", "0,1,0,1,"})
    EXPECT_EQ(error_parameter([&] { parse_crop(bad); }), "--crop") << bad;
}

TEST(RenderRequest, OverridesReachTheSetup) {
  const SceneDescription desc = parse_scene_string(kScene, "t.pbrt", ".");
  RenderSetup plain = build_requested_setup(desc, {});
  EXPECT_EQ(plain.film->resolution(), IVec2(8, 6));
  EXPECT_EQ(plain.sampler->samples_per_pixel(), 4);
  RenderRequest r;
  r.resolution = "20x10";
  r.crop = "0,0.5,0,1";
  r.spp = 9;
  r.camera = "Camera \"thinlens\" \"float lensradius\" 0.25 \"float fov\" 50";
  RenderSetup s = build_requested_setup(desc, r);
  EXPECT_EQ(s.film->resolution(), IVec2(20, 10));
  EXPECT_EQ(s.film->bounds().width(), 10);  // half the width, as the crop asks
  EXPECT_EQ(s.film->bounds().height(), 10);
  EXPECT_EQ(s.sampler->samples_per_pixel(), 9);
  EXPECT_NE(s.camera->to_string().find("fov 50 deg, lens radius 0.25"), std::string::npos) << s.camera->to_string();
  EXPECT_NE(plain.camera->to_string().find("fov 30 deg, lens radius 0,"), std::string::npos)
      << plain.camera->to_string();
}

TEST(RenderRequest, RefusesBadNumbers) {
  RenderRequest r;
  r.spp = -1;
  EXPECT_EQ(error_parameter([&] { render_overrides(r); }), "--spp");
  r.spp = 0;
  r.max_memory_gib = -1;
  EXPECT_EQ(error_parameter([&] { render_overrides(r); }), "--max-memory");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
