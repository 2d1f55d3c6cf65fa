// The gbuffer film's auxiliary channels (pbrt-v4's GBufferFilm): the variance against the
// textbook sample variance, and through the renderer a plane whose position, normal, (u, v)
// and albedo are known.
#include "render/gbuffer.h"
#include "../support/unity_id.h"

#include <regex>

#include <gtest/gtest.h>

#include <map>

#include "../support/render_text.h"
#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::map<std::string, int> channel_index() {
  std::map<std::string, int> m;
  const auto& names = GBuffer::channel_names();
  for (int i = 0; i < GBuffer::kChannels; ++i) m[names[i]] = i;
  return m;
}

// Four samples that saw a surface with red 1, 2, 3, 4 (and one that saw nothing, which does not
// count): the sample variance is 5/3, its mean 2.5, so the relative variance (pbrt-v4's: variance
// over mean) is 2/3; the film's scale s multiplies the colours, the variance by s^2.
TEST(GBuffer, VarianceIsTheSampleVarianceOfTheColours) {
  GBuffer g(1, AnimatedTransform());
  VisibleSurface vs;
  vs.set = true;
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
  for (float r : {1.f, 2.f, 3.f, 4.f}) g.add(0, vs, lambda, RGB(r, 2.f * r, 7.f), 1.f);
  g.add(0, VisibleSurface{}, lambda, RGB(100.f), 1.f);
  auto ch = channel_index();
  float out[GBuffer::kChannels];
  g.channels(0, 5.0, 2.f, out);
  EXPECT_NEAR(out[ch["Variance.R"]], 4.0 * 5.0 / 3.0, 1e-5);
  EXPECT_NEAR(out[ch["Variance.G"]], 4.0 * 4.0 * 5.0 / 3.0, 1e-5);
  EXPECT_EQ(out[ch["Variance.B"]], 0.f);
  EXPECT_NEAR(out[ch["RelativeVariance.R"]], 2.0 * (5.0 / 3.0) / 2.5, 1e-5);
  EXPECT_NEAR(out[ch["RelativeVariance.G"]], 2.0 * (4.0 * 5.0 / 3.0) / 5.0, 1e-5);
  // One sample: no variance (pbrt-v4's VarianceEstimator needs two).
  GBuffer one(1, AnimatedTransform());
  one.add(0, vs, lambda, RGB(3.f), 1.f);
  one.channels(0, 1.0, 1.f, out);
  EXPECT_EQ(out[ch["Variance.R"]], 0.f);
}

// A 2 x 2 plane z = 0 with u = (x + 1) / 2, v = (y + 1) / 2, seen from z = 5 (pbrt's LookAt,
// camera space +z forward). In camera space every sample's point is at depth 5 exactly and the
// normal facing the camera is (0, 0, -1); in world space it is (0, 0, 1), and since u and v are
// linear in x and y, each pixel's mean (u, v) is ((P.X + 1) / 2, (P.Y + 1) / 2) of its mean
// point, whatever the samples. A grey diffuse reflectance 0.5 has albedo 0.5 for every sampled
// direction (f cos / pdf = R for cosine sampling), so a pixel wholly on the plane has albedo 0.5
// within the colour estimate's noise (1 %), pixels off it 0, and every channel is finite.
std::string plane(const std::string& space) {
  return R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 30
    Film "gbuffer" "integer xresolution" 16 "integer yresolution" 16 "string coordinatesystem" ")" +
         space + R"("
    PixelFilter "box"
    Sampler "independent" "integer pixelsamples" 64
    WorldBegin
    LightSource "infinite" "rgb L" [1 1 1]
    Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
      "point2 uv" [0 0  1 0  1 1  0 1]
  )";
}

TEST(GBuffer, APlanesPositionNormalUvAndAlbedo) {
  auto ch = channel_index();
  const Image cam = test::render_text(plane("camera")), world = test::render_text(plane("world"));
  ASSERT_EQ(cam.channels, 3 + GBuffer::kChannels);
  ASSERT_EQ(cam.channel_names[3 + ch["P.Z"]], "P.Z");
  int inside = 0, outside = 0;
  double albedo_sum = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      auto c = [&](const Image& im, const char* n) { return im.at(x, y, 3 + ch[n]); };
      for (int k = 0; k < cam.channels; ++k) ASSERT_TRUE(std::isfinite(cam.at(x, y, k)));
      // Pixels whose whole footprint is on the plane: the plane spans 2 / (2 * 5 tan 15 deg) of
      // the view, about 6 of the 16 pixels either side of the centre.
      const bool on = std::abs(x - 7.5) < 5 && std::abs(y - 7.5) < 5;
      const bool off = std::abs(x - 7.5) > 7 || std::abs(y - 7.5) > 7;
      if (on) {
        ++inside;
        EXPECT_NEAR(c(cam, "P.Z"), 5.f, 1e-4f);
        EXPECT_NEAR(c(cam, "N.Z"), -1.f, 1e-6f);
        EXPECT_NEAR(c(cam, "Ns.Z"), -1.f, 1e-6f);
        EXPECT_NEAR(c(world, "N.Z"), 1.f, 1e-6f);
        EXPECT_NEAR(c(world, "P.Z"), 0.f, 1e-5f);
        EXPECT_NEAR(c(world, "u"), (c(world, "P.X") + 1.f) / 2.f, 1e-5f);
        EXPECT_NEAR(c(world, "v"), (c(world, "P.Y") + 1.f) / 2.f, 1e-5f);
        // The same samples (same seed) in the two spaces: pbrt's LookAt from +z towards the origin
        // with up +y makes camera x = -world x (right = up x forward), camera y = world y.
        EXPECT_NEAR(c(cam, "P.X"), -c(world, "P.X"), 1e-5f);
        EXPECT_NEAR(c(cam, "P.Y"), c(world, "P.Y"), 1e-5f);
        for (const char* a : {"Albedo.R", "Albedo.G", "Albedo.B"}) albedo_sum += c(cam, a);
      }
      if (off) {
        ++outside;
        for (const char* n : {"Albedo.G", "P.Z", "N.Z", "u", "Variance.G"}) EXPECT_EQ(c(cam, n), 0.f) << n;
      }
    }
  ASSERT_GT(inside, 50);
  ASSERT_GT(outside, 20);
  EXPECT_NEAR(albedo_sum / (3 * inside), 0.5, 0.005);
}

// A camera sliding sideways (parallel to the plane) during the shutter sees every film point at
// the same camera-space point at every time: its camera-space channels must equal the still
// camera's, sample for sample (the same seed draws the same film positions; the time is the
// sample's own). Taken at the start time instead (as before), P.X would be off by up to 1, by
// 0.5 on average.
TEST(GBuffer, AMovingCamerasSpaceIsTakenAtEachSamplesTime) {
  auto ch = channel_index();
  auto scene = [](const std::string& motion) {
    return R"(
    LookAt 0 0 5  0 0 0  0 1 0
    )" + motion +
           R"(
    Camera "perspective" "float fov" 30
    Film "gbuffer" "integer xresolution" 8 "integer yresolution" 8
    PixelFilter "box"
    Sampler "independent" "integer pixelsamples" 16
    WorldBegin
    LightSource "infinite" "rgb L" [1 1 1]
    Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-9 -9 0  9 -9 0  9 9 0  -9 9 0]
  )";
  };
  const Image still = test::render_text(scene(""));
  const Image moving = test::render_text(scene("ActiveTransform EndTime\n Translate 1 0 0\n ActiveTransform All"));
  double worst = 0, start_time_offset = 0;
  for (int y = 0; y < still.height; ++y)
    for (int x = 0; x < still.width; ++x)
      for (const char* n : {"P.X", "P.Y", "P.Z", "N.Z"}) {
        const double d = moving.at(x, y, 3 + ch[n]) - still.at(x, y, 3 + ch[n]);
        worst = std::max(worst, std::abs(d));
      }
  // The world-space points did move: the moving camera's world P.X differs (a check that the
  // scene moves at all).
  const Image moving_world = test::render_text(std::regex_replace(
      scene("ActiveTransform EndTime\n Translate 1 0 0\n ActiveTransform All"), std::regex("\"integer yresolution\" 8"),
      "\"integer yresolution\" 8 \"string coordinatesystem\" \"world\""));
  const Image still_world =
      test::render_text(std::regex_replace(scene(""), std::regex("\"integer yresolution\" 8"),
                                           "\"integer yresolution\" 8 \"string coordinatesystem\" \"world\""));
  for (int y = 0; y < still.height; ++y)
    for (int x = 0; x < still.width; ++x)
      start_time_offset += std::abs(moving_world.at(x, y, 3 + ch["P.X"]) - still_world.at(x, y, 3 + ch["P.X"]));
  start_time_offset /= still.width * still.height;
  EXPECT_LT(worst, 1e-4);
  EXPECT_NEAR(start_time_offset, 0.5, 0.1);
}

// dzdx and dzdy of a plane tilted by 30 degrees about the camera's y axis, z = 5 + x tan 30 in
// camera space (camera at the origin looking down +z, so camera space is world space moved by 5).
// A ray of slope a = x / z meets it at depth z(a) = 5 / (1 - a tan 30), so one pixel step (slope
// step 2 tan 15 / 16 across the 30-degree, 16-pixel film), scaled by pbrt-v4's 1 / sqrt(spp) =
// 1/4 at 16 spp, moves the depth by (1/4)(2 tan 15 / 16) z'(a), z'(a) = 5 tan 30 / (1 - a tan 30)^2
// (to first order; the second-order term is 0.5 % of it). The slope a is each pixel's mean P.X / P.Z.
// Along y the depth does not change: a ray moved in y keeps its slope a, so dzdy is 0.
TEST(GBuffer, DepthDerivativesOfATiltedPlane) {
  auto ch = channel_index();
  const Image im = test::render_text(R"(
    LookAt 0 0 -5  0 0 0  0 1 0
    Camera "perspective" "float fov" 30
    Film "gbuffer" "integer xresolution" 16 "integer yresolution" 16
    PixelFilter "box"
    Sampler "independent" "integer pixelsamples" 16
    WorldBegin
    LightSource "infinite" "rgb L" [1 1 1]
    Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
    Rotate -30 0 1 0
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-9 -9 0  9 -9 0  9 9 0  -9 9 0]
  )");
  const double t30 = std::tan(30.0 * kPi / 180.0), step = 0.25 * 2.0 * std::tan(15.0 * kPi / 180.0) / 16.0;
  int checked = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      auto c = [&](const char* n) { return double(im.at(x, y, 3 + ch[n])); };
      const double a = c("P.X") / c("P.Z");
      ASSERT_NEAR(c("P.Z"), 5.0 / (1.0 - a * t30), 1e-3) << "the plane is not where the test assumes";
      const double expected = step * 5.0 * t30 / ((1.0 - a * t30) * (1.0 - a * t30));
      EXPECT_NEAR(c("dzdx"), expected, 0.02 * expected) << x << " " << y;
      EXPECT_NEAR(c("dzdy"), 0.0, 1e-3 * expected) << x << " " << y;
      ++checked;
    }
  EXPECT_EQ(checked, 256);
}

// Bad input: an output other than EXR, and an unknown coordinate system, name the parameter.
TEST(GBuffer, FilmRefusesPngAndUnknownCoordinateSystems) {
  std::string text = plane("camera");
  text.replace(text.find("\"integer xresolution\""), 0, "\"string filename\" \"out.png\" ");
  EXPECT_THROW(test::render_text(text), SceneError);
  EXPECT_THROW(test::render_text(plane("screen")), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
