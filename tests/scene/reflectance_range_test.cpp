// An RGB reflectance above 1 (or below 0) is no reflectance at all. The issue asks for "a clear
// error or a stated clamp with a warning, naming the file, line and parameter": eyetrace clamps
// to [0, 1] and warns (an error with --strict); the render is that of the clamped colour.
#include <gtest/gtest.h>

#include <string>

#include "../support/unity_id.h"
#include "core/error.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// A diffuse sphere filling the view in a uniform white environment reflects exactly its
// albedo (one bounce, then the light): the rendered colour is the reflectance.
std::string furnace(const std::string& material) {
  return R"(LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 10
Film "rgb" "integer xresolution" 8 "integer yresolution" 8
Sampler "halton" "integer pixelsamples" 64
Integrator "path" "integer maxdepth" 2
PixelFilter "box"
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
)" + material +
         "\nShape \"sphere\" \"float radius\" 1\n";
}

struct Rendered {
  Image image;
  std::string warnings;  // what the scene's parse and build wrote to stderr
};

Rendered render(const std::string& text, const std::string& file) {
  testing::internal::CaptureStderr();
  SceneDescription desc = parse_scene_string(text, file, ".");
  RenderSetup s = build_render_setup(desc, {});
  Rendered r;
  r.warnings = testing::internal::GetCapturedStderr();
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
  r.image = s.film->image();
  return r;
}

double channel_mean(const Image& img, int c) {
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, c);
  return sum / (double(img.width) * img.height);
}

TEST(ReflectanceRange, AboveOneIsClampedWithAWarningNamingFileLineAndParameter) {
  // Line 9 of the scene; the parameter's declaration starts in column 20.
  const Rendered over = render(furnace(R"(Material "diffuse" "rgb reflectance" [1.5 0.5 0.2])"), "over_one.pbrt");
  EXPECT_NE(over.warnings.find("over_one.pbrt:9:20: warning: parameter \"reflectance\": RGB (1.5, 0.5, 0.2)"),
            std::string::npos)
      << over.warnings;
  EXPECT_NE(over.warnings.find("clamped to (1, 0.5, 0.2)"), std::string::npos) << over.warnings;

  // The render is the clamped colour's, bit for bit (same seed, same spectrum), and that colour
  // is (1, 0.5, 0.2): the spectral round trip and 4096 samples leave well under 2 % per channel.
  const Rendered in_range = render(furnace(R"(Material "diffuse" "rgb reflectance" [1 0.5 0.2])"), "in_range.pbrt");
  EXPECT_EQ(in_range.warnings, "");
  ASSERT_EQ(over.image.pixels.size(), in_range.image.pixels.size());
  EXPECT_TRUE(over.image.pixels == in_range.image.pixels);
  const double want[3] = {1.0, 0.5, 0.2};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(channel_mean(over.image, c), want[c], 0.02 * want[c]) << "channel " << c;
}

TEST(ReflectanceRange, NegativeComponentsAndTextureConstantsAreWarnedToo) {
  const Rendered r = render(furnace(R"(Texture "paint" "spectrum" "constant" "rgb value" [-0.25 0.5 2]
Material "diffuse" "texture reflectance" "paint")"),
                            "texture_over_one.pbrt");
  EXPECT_NE(r.warnings.find("texture_over_one.pbrt:9:39: warning: parameter \"value\": RGB (-0.25, 0.5, 2)"),
            std::string::npos)
      << r.warnings;
  EXPECT_NE(r.warnings.find("clamped to (0, 0.5, 1)"), std::string::npos) << r.warnings;
}

TEST(ReflectanceRange, ConstantSpectraAreWarnedAsSuch) {
  const Rendered r = render(furnace(R"(Material "diffuse" "spectrum reflectance" [1.25])"), "spectrum_over_one.pbrt");
  EXPECT_NE(r.warnings.find("spectrum_over_one.pbrt:9:20: warning: parameter \"reflectance\": the constant spectrum "
                            "1.25 is read as a reflectance, which lies in [0, 1]; clamped to 1"),
            std::string::npos)
      << r.warnings;
}

TEST(ReflectanceRange, IndicesOfRefractionAreNotReflectances) {
  const Rendered r =
      render(furnace(R"(Material "conductor" "rgb eta" [1.5 1.2 1.1] "rgb k" [3 2.5 2])"), "conductor_eta.pbrt");
  EXPECT_EQ(r.warnings, "");
}

TEST(ReflectanceRange, StrictMakesTheWarningAnError) {
  set_warnings_fatal(true);
  try {
    build_render_setup(
        parse_scene_string(furnace(R"(Material "diffuse" "rgb reflectance" [1 1.01 1])"), "strict.pbrt", "."), {});
    ADD_FAILURE() << "no error for a reflectance above 1 with strict warnings";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("strict.pbrt:9:20: error: parameter \"reflectance\""), std::string::npos)
        << e.what();
  }
  set_warnings_fatal(false);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
