// Two things pbrt-v4-scenes write that today's pbrt-v4 refuses or deprecates: Film
// "float scale" multiplies the image (as earlier pbrt-v4 did), and `Material ""` is the
// interface material (no surface: rays pass through); and the exposure time, which pbrt-v4
// takes from the camera's shutter interval. The first two are
// checked against the same render without them (the interface material: with "interface" by name), with the same seed,
// so the samples are the same ones.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Image render(const std::string& film_extra, const std::string& world_extra, const std::string& camera_extra = "") {
  const std::string text = "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30 " + camera_extra +
                           "\n"
                           "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8 " +
                           film_extra +
                           "\nSampler \"independent\" \"integer pixelsamples\" 4\nWorldBegin\n"
                           "LightSource \"infinite\" \"rgb L\" [0.7 0.5 0.3]\n"
                           "AttributeBegin\nTranslate 0.3 0 0\nMaterial \"diffuse\" \"rgb reflectance\" [0.5 0.6 0.7]\n"
                           "Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n" +
                           world_extra;
  RenderSetup s = build_render_setup(parse_scene_string(text, "t.pbrt", "."), {});
  RenderCounters c;
  RenderOptions o;
  o.threads = 1;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, c);
  return s.film->image();
}

TEST(FilmScale, MultipliesTheImage) {
  const Image plain = render("", "");
  const Image scaled = render("\"float scale\" 2.5", "");
  ASSERT_EQ(plain.pixels.size(), scaled.pixels.size());
  double sum = 0;
  for (size_t i = 0; i < plain.pixels.size(); ++i) {
    EXPECT_NEAR(scaled.pixels[i], 2.5f * plain.pixels[i], 1e-5f * std::abs(plain.pixels[i]) + 1e-7f) << i;
    sum += plain.pixels[i];
  }
  EXPECT_GT(sum, 0.0);
}

// A sphere around the lit one, made of the empty material, renders as one made of
// "interface" (pbrt-v4 reads "" and "none" as "interface"), and not as the default diffuse
// material would.
TEST(InterfaceMaterial, EmptyNameIsTheInterfaceMaterial) {
  const Image plain = render("", "Material \"interface\"\nShape \"sphere\" \"float radius\" 1.2\n");
  const Image diffuse = render("", "Material \"diffuse\"\nShape \"sphere\" \"float radius\" 1.2\n");
  double differs = 0;
  for (size_t i = 0; i < plain.pixels.size(); ++i) differs += std::abs(plain.pixels[i] - diffuse.pixels[i]);
  EXPECT_GT(differs, 0.1);
  for (const char* name : {"\"\"", "\"none\""}) {
    const Image with = render("", std::string("Material ") + name + "\nShape \"sphere\" \"float radius\" 1.2\n");
    ASSERT_EQ(plain.pixels.size(), with.pixels.size());
    for (size_t i = 0; i < plain.pixels.size(); ++i)
      EXPECT_NEAR(with.pixels[i], plain.pixels[i], 1e-5f * std::abs(plain.pixels[i]) + 1e-7f) << name << " " << i;
  }
}

// pbrt-v4's film takes the exposure time from the camera, shutterclose - shutteropen; ISO 200
// doubles it, eyetrace's own Film "exposuretime" multiplies it. Nothing moves while the shutter
// is open, so the same samples give the image times 2 x 0.4 x 1.5 = 1.2.
TEST(FilmExposure, TheCameraShutterIntervalIsTheExposureTime) {
  const Image plain = render("", "");
  const Image exposed = render("\"float iso\" 200 \"float exposuretime\" 1.5", "",
                               "\"float shutteropen\" 0.1 \"float shutterclose\" 0.5");
  ASSERT_EQ(plain.pixels.size(), exposed.pixels.size());
  for (size_t i = 0; i < plain.pixels.size(); ++i)
    EXPECT_NEAR(exposed.pixels[i], 1.2f * plain.pixels[i], 1e-5f * std::abs(plain.pixels[i]) + 1e-7f) << i;
  std::string e;
  try {
    render("", "", "\"float shutteropen\" 0.5 \"float shutterclose\" 0.5");
  } catch (const SceneError& err) {
    e = err.what();
  }
  EXPECT_NE(e.find("t.pbrt:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("shutterclose"), std::string::npos) << e;
  EXPECT_NE(e.find("never opens"), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
