// Alpha cutouts (pbrt-v4's "alpha", shapes/shape_alpha.h): through the renderer, a quad in front
// of an emitter hides it with alpha 1, is not there with alpha 0, passes a fraction 1 - alpha of
// the camera rays in between (a binomial mean, 4 sigma), follows a texture's pattern exactly,
// and casts no shadow where it is cut out; an area light on a cut-out shape emits only where the
// shape is, and one of constant alpha 0 is an invisible emitter that still lights; the quadrics likewise (a sphere,
// whose two crossings a ray passes or not together, since one hash decides both; a disk and a cylinder cut out).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/render_text.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Image render(const std::string& text) { return test::render_text(text, "alpha.pbrt"); }

double mean(const Image& img, int x0 = 0, int x1 = -1) { return test::channel_mean(img, 1, x0, x1); }

// A black quad (z = 0, uv over it) seen from +z in front of an emitter of radiance 1 (z = -1),
// with the given alpha parameter text; 16 x 16 pixels, `spp` samples each.
std::string pane(const std::string& alpha, int spp = 16, const std::string& textures = "") {
  return fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "independent" "integer pixelsamples" {}
    PixelFilter "box"
    Integrator "path" "integer maxdepth" 5
    WorldBegin
    {}
    AttributeBegin
      Material "diffuse" "rgb reflectance" [0 0 0]
      AreaLightSource "diffuse" "rgb L" [1 1 1]
      Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-3 -3 -1  3 -3 -1  3 3 -1  -3 3 -1]
    AttributeEnd
    Material "diffuse" "rgb reflectance" [0 0 0]
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
      "point2 uv" [0 0  1 0  1 1  0 1] {}
  )",
                     spp, textures, alpha);
}

TEST(AlphaCutout, OpaqueHiddenAndHalfway) {
  EXPECT_NEAR(mean(render(pane(""))), 0.0, 1e-6);                    // no alpha: opaque
  EXPECT_NEAR(mean(render(pane(R"("float alpha" 1)"))), 0.0, 1e-6);  // 1: opaque
  // 0: not there (1 within the colour noise of 4 sampled wavelengths per camera ray).
  EXPECT_NEAR(mean(render(pane(R"("float alpha" 0)"))), 1.0, 1e-3);
  // 0.3: each camera ray passes with probability 0.7 (emitter 1) or stops on the black quad.
  const int n = 16 * 16 * 64;
  EXPECT_NEAR(mean(render(pane(R"("float alpha" 0.3)", 64))), 0.7, 4 * std::sqrt(0.7 * 0.3 / n));
}

TEST(AlphaCutout, ATexturedAlphaCutsItsPattern) {
  // A checkerboard of two columns across the quad (uscale 2): alpha 1 where u < 1/2 (x < 0), 0
  // where u > 1/2, which shows the emitter. pbrt's LookAt from +z puts world +x on the image's
  // left, so the left half shows the emitter and the right stays black. The quad fills the
  // view (fov 10 at distance 5 sees +-0.44), so the halves are the image's.
  const Image img = render(pane(R"("texture alpha" "cut")", 4,
                                R"(Texture "cut" "float" "checkerboard" "float uscale" 2 "float vscale" 1
                                    "float tex1" 1 "float tex2" 0)"));
  EXPECT_NEAR(mean(img, 0, 7), 1.0, 2e-3);
  EXPECT_NEAR(mean(img, 9, 16), 0.0, 1e-6);
}

TEST(AlphaCutout, ACutOutOccluderCastsNoShadow) {
  // A floor (z = 0) lit by a distant light from direction (0, 1, 1); a quad at z = 1 over
  // y in [0.2, 5] shadows the floor around the origin, which the camera sees past the quad's
  // edge (its rays cross z = 1 near y = -0.1): alpha 1 shadows it, alpha 0 does not.
  auto scene = [](const std::string& alpha) {
    return fmt::format(R"(
      LookAt 0 -0.5 5  0 0 0  0 1 0
      Camera "perspective" "float fov" 2
      Film "rgb" "integer xresolution" 8 "integer yresolution" 8
      Sampler "independent" "integer pixelsamples" 4
      Integrator "path" "integer maxdepth" 1
      WorldBegin
      LightSource "distant" "point3 from" [0 10 10] "point3 to" [0 0 0] "rgb L" [1 1 1]
      Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
      Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-5 -5 0  5 -5 0  5 5 0  -5 5 0]
      Material "diffuse" "rgb reflectance" [0 0 0]
      Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-5 0.2 1  5 0.2 1  5 5 1  -5 5 1] {}
    )",
                       alpha);
  };
  const double lit = 0.5 / 3.14159265358979 * std::sqrt(0.5);  // R / pi E cos 45 with E = 1
  EXPECT_NEAR(mean(render(scene(R"("float alpha" 0)"))), lit, 1e-3 * lit + 1e-5);
  EXPECT_NEAR(mean(render(scene(R"("float alpha" 1)"))), 0.0, 1e-6);
  EXPECT_NEAR(mean(render(scene(""))), 0.0, 1e-6);
}

// The quad of pane() replaced by another shape with the given alpha.
std::string shape_before_emitter(const std::string& shape, int spp = 16) {
  std::string text = pane("", spp);
  const size_t at = text.rfind("Shape \"trianglemesh\"");
  return text.substr(0, at) + shape + "\n";
}

TEST(AlphaCutout, QuadricsCutOutToo) {
  const int n = 16 * 16 * 64;
  for (const char* shape : {R"(Shape "sphere" "float radius" 2)", R"(Shape "disk" "float radius" 2)",
                            R"(Translate 0 0 -0.5 Rotate 90 1 0 0 Shape "cylinder" "float radius" 3 "float zmin" -3
                               "float zmax" 3)"}) {
    const std::string s = shape;
    // Opaque (black) in front of the emitter, then cut out entirely, then 30 %: the emitter's
    // 1 seen through 70 % of the rays (4 sigma).
    EXPECT_NEAR(mean(render(shape_before_emitter(s, 4))), 0.0, 1e-6) << s;
    EXPECT_NEAR(mean(render(shape_before_emitter(s + R"( "float alpha" 0)", 4))), 1.0, 1e-3) << s;
    EXPECT_NEAR(mean(render(shape_before_emitter(s + R"( "float alpha" 0.3)", 64))), 0.7, 4 * std::sqrt(0.7 * 0.3 / n))
        << s;
  }
}

// A camera halfway between a diffuse floor (z = 0, albedo 1/2) and a 1 x 1 quad light facing it
// at z = 1, looking straight down at the floor's centre through a narrow view; the light's
// alpha is given. With a 2 x 2 checkerboard alpha, a quarter turn about the axis swaps the cut
// and the kept squares and leaves the floor's centre where it is, so the centre receives
// exactly half the irradiance of the whole light (the patch seen is +-0.02 wide, where the
// change is second order: below 1e-3).
std::string floor_under_light(const std::string& alpha) {
  return fmt::format(R"(
    LookAt 0 0 0.5  0 0 0  0 1 0
    Camera "perspective" "float fov" 5
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "independent" "integer pixelsamples" 64
    PixelFilter "box"
    Integrator "path" "integer maxdepth" 1
    WorldBegin
    Texture "checks" "float" "checkerboard" "float uscale" 2 "float vscale" 2 "float tex1" 1 "float tex2" 0
    Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-3 -3 0  3 -3 0  3 3 0  -3 3 0]
    AttributeBegin
      AreaLightSource "diffuse" "rgb L" [1 1 1]
      Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-0.5 -0.5 1  -0.5 0.5 1  0.5 0.5 1  0.5 -0.5 1]
        "point2 uv" [0 0  0 1  1 1  1 0] {}
    AttributeEnd
  )",
                     alpha);
}

TEST(AlphaCutout, AreaLightsEmitOnlyWhereTheShapeIsAndInvisibleOnesStillLight) {
  const double whole = mean(render(floor_under_light("")));
  EXPECT_GT(whole, 0.05);
  // Light sampling alone reaches the floor here (maxdepth 1, diffuse): 16384 samples, most
  // within 30 % of the mean, so 2 % is several standard errors of the ratio.
  EXPECT_NEAR(mean(render(floor_under_light(R"("texture alpha" "checks")"))) / whole, 0.5, 0.02);
  // Constant alpha 0: no ray meets the light, which still lights the floor fully.
  EXPECT_NEAR(mean(render(floor_under_light(R"("float alpha" 0)"))) / whole, 1.0, 0.02);
  // ... and is not seen: looking up at it shows nothing.
  std::string up = floor_under_light(R"("float alpha" 0)");
  up.replace(up.find("LookAt 0 0 0.5  0 0 0"), 21, "LookAt 0 0 0.5  0 0 1");
  EXPECT_EQ(mean(render(up)), 0.0);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
