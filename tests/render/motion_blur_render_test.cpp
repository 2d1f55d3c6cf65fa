// Motion blur rendered, against answers computed here without the renderer: a black sphere
// sliding across a uniform sky through a pinhole darkens each pixel by the fraction of pixel
// area and shutter time it covers (a box filter: the pixel's own samples only); a black square
// spinning 90 degrees about the view axis gives the rotationally averaged coverage; a hit on a
// moving sphere lies on the sphere where it is at the ray's time, with its normal; a lit sphere
// turning about its own centre looks like the still one (a mismatch between the surface Embree
// traces and the one rebuilt for shading would show as self-shadowing, a darker mean). The
// coverage expected per pixel is integrated on a 12 x 12 grid in the pixel and 48 times.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>

#include "../support/unity_id.h"
#include "core/constants.h"
#include "core/error.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/scene.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

RenderSetup setup_for(const std::string& text) {
  SceneDescription desc = parse_scene_string(text, "motion.pbrt", ".");
  return build_render_setup(desc, RenderOverrides{});
}

Image render(const std::string& text, uint64_t seed) {
  SceneDescription desc = parse_scene_string(text, "motion.pbrt", ".");
  RenderOverrides o;
  o.seed = seed;
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  RenderOptions options;
  options.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, options, counters);
  return s.film->image();
}

// pbrt's pinhole through raster point (x, y) of a W x H image, fov across the shorter (y)
// axis, camera at the origin looking down +z with +x to the right of the image.
Vec3 pinhole_direction(float x, float y, int w, int h, float fov_deg) {
  const float t = std::tan(fov_deg * kPi / 360.f), aspect = float(w) / float(h);
  return Vec3((-aspect + 2.f * aspect * x / w) * t, (1.f - 2.f * y / h) * t, 1.f);
}

// Fraction of pixel (px, py)'s area and of the shutter [0, 1] in which `covered(d, time)` holds.
double coverage(int px, int py, int w, int h, float fov, const std::function<bool(Vec3, float)>& covered) {
  constexpr int kGrid = 12, kTimes = 48;
  int hits = 0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      for (int k = 0; k < kTimes; ++k) {
        Vec3 d = pinhole_direction(px + (i + 0.5f) / kGrid, py + (j + 0.5f) / kGrid, w, h, fov);
        hits += covered(d, (k + 0.5f) / kTimes);
      }
  return double(hits) / (kGrid * kGrid * kTimes);
}

// Every pixel is sky radiance times (1 - coverage): asserted within 5 binomial standard errors
// (spp samples each, one Bernoulli trial of "covered" per sample) plus the grid's own
// discretisation (0.01). The sky's radiance is read from pixels nothing covers.
void expect_smear(const Image& im, int spp, float fov, const std::function<bool(Vec3, float)>& covered) {
  std::vector<double> f(size_t(im.width) * im.height);
  double sky = 0;
  int sky_pixels = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      f[size_t(y) * im.width + x] = coverage(x, y, im.width, im.height, fov, covered);
      if (f[size_t(y) * im.width + x] == 0.0) sky += im.at(x, y, 1), ++sky_pixels;
    }
  ASSERT_GT(sky_pixels, 10);
  sky /= sky_pixels;
  ASSERT_GT(sky, 0.5);
  int partial = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const double fx = f[size_t(y) * im.width + x];
      partial += fx > 0.05 && fx < 0.95;
      const double got = 1.0 - im.at(x, y, 1) / sky;
      const double sigma = std::sqrt(fx * (1 - fx) / spp);
      EXPECT_NEAR(got, fx, 5 * sigma + 0.01) << "pixel " << x << ", " << y;
    }
  EXPECT_GT(partial, 20);  // the smear, not only fully covered or empty pixels, was checked
}

const char* kSkyCamera = R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "pinhole" "float fov" 20
Film "rgb" "integer xresolution" 48 "integer yresolution" 12
PixelFilter "box"
Sampler "independent" "integer pixelsamples" 256
Integrator "path" "integer maxdepth" 1
)";

TEST(MotionBlurRender, SlidingSphereSmearsByTheFractionOfTimeItCoversEachPixel) {
  const std::string text = fmt::format("{}{}", kSkyCamera, R"(WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "diffuse" "rgb reflectance" [0 0 0]
Translate -1.2 0 5
ActiveTransform EndTime
Translate 2.4 0 0
ActiveTransform All
Shape "sphere" "float radius" 0.5
)");
  expect_smear(render(text, 1), 256, 20.f, [](Vec3 d, float t) {
    const Vec3 c(-1.2f + 2.4f * t, 0.f, 5.f);
    // The ray from the origin along d meets the sphere iff its distance from c is under r.
    const Vec3 u = glm::normalize(d);
    return glm::length(c - glm::dot(c, u) * u) < 0.5f;
  });
}

TEST(MotionBlurRender, SquareSpinningAboutTheViewAxisGivesTheRotationalAverage) {
  const std::string text = R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "pinhole" "float fov" 20
Film "rgb" "integer xresolution" 24 "integer yresolution" 24
PixelFilter "box"
Sampler "independent" "integer pixelsamples" 256
Integrator "path" "integer maxdepth" 1
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "diffuse" "rgb reflectance" [0 0 0]
Translate 0 0 5
ActiveTransform EndTime
Rotate 90 0 0 1
ActiveTransform All
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-0.6 -0.6 0  0.6 -0.6 0  0.6 0.6 0  -0.6 0.6 0]
)";
  expect_smear(render(text, 2), 256, 20.f, [](Vec3 d, float t) {
    const Vec3 p = d * (5.f / d.z);  // on the square's plane
    const float a = -0.5f * kPi * t, c = std::cos(a), s = std::sin(a);
    const float x = c * p.x - s * p.y, y = s * p.x + c * p.y;  // into the square's frame
    return std::abs(x) < 0.6f && std::abs(y) < 0.6f;
  });
}

TEST(MotionBlurRender, HitOnAMovingSphereIsWhereTheSphereIsAtTheRayTime) {
  RenderSetup s = setup_for(R"(TransformTimes 2 4
WorldBegin
Translate 0 0 5
ActiveTransform EndTime
Translate 3 0 0
Rotate 70 1 1 0
ActiveTransform All
Shape "sphere" "float radius" 1
)");
  ASSERT_TRUE(s.scene->has_motion());
  for (float time : {1.f, 2.5f, 3.f, 3.9f, 7.f}) {
    const float u = std::clamp((time - 2.f) / 2.f, 0.f, 1.f);
    const Vec3 centre(3.f * u, 0.f, 5.f);
    Ray ray{Vec3(0.f), glm::normalize(centre + Vec3(0.3f, 0.4f, 0.f)), kInfinity, time};
    SurfaceInteraction si;
    ASSERT_TRUE(s.scene->intersect(ray, &si)) << time;
    EXPECT_NEAR(glm::length(si.p - centre), 1.f, 1e-4f) << time;
    EXPECT_NEAR(glm::dot(si.n, (si.p - centre)), 1.f, 1e-4f) << time;  // the outward normal there
    EXPECT_NEAR(glm::length(si.p - ray.at(si.t)), 0.f, 1e-4f) << time;
    EXPECT_EQ(si.time, time);
  }
}

// A moving shape inside an object moves at every use of the object: the sphere slides 2 along
// object x over the shutter, placed by two still uses 3 apart in y. At time 0.5 each copy is
// centred at object x = 1; at time 0 at x = 0.
TEST(MotionBlurRender, MovingShapeInsideAnObjectMovesAtEachUse) {
  WarningCollector warnings;
  RenderSetup s = setup_for(R"(WorldBegin
ObjectBegin "o"
ActiveTransform EndTime
Translate 2 0 0
ActiveTransform All
Shape "sphere" "float radius" 0.5
ObjectEnd
AttributeBegin
Translate 0 0 5
ObjectInstance "o"
AttributeEnd
Translate 0 3 5
ObjectInstance "o"
)");
  EXPECT_TRUE(warnings.warnings().empty());
  for (float y : {0.f, 3.f}) {
    for (auto [time, x, hits] : {std::tuple{0.5f, 1.f, true}, std::tuple{0.f, 0.f, true},
                                 std::tuple{0.5f, -0.2f, false}, std::tuple{1.f, 2.f, true}}) {
      Ray ray{Vec3(x, y, 0.f), Vec3(0, 0, 1), kInfinity, time};
      SurfaceInteraction si;
      ASSERT_EQ(s.scene->intersect(ray, &si), hits) << "y " << y << " time " << time << " x " << x;
      if (!hits) continue;
      EXPECT_NEAR(si.t, 4.5f, 1e-4f);
      EXPECT_NEAR(glm::length(si.n - Vec3(0, 0, -1)), 0.f, 1e-4f);
    }
  }
}

// Under a moving use, pbrt-v4 multiplies the use's and the shape's interpolated motions; two
// keyframes cannot hold that product, so the combination is said at the ObjectInstance's line.
TEST(MotionBlurRender, MovingUseOfAnObjectWithMovingShapesIsWarned) {
  WarningCollector warnings;
  RenderSetup s = setup_for(R"(WorldBegin
ObjectBegin "o"
ActiveTransform EndTime
Rotate 30 0 1 0
ActiveTransform All
Shape "sphere"
ObjectEnd
ActiveTransform EndTime
Translate 0 1 0
ActiveTransform All
ObjectInstance "o"
)");
  const std::vector<Diagnostic> w = warnings.warnings();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].loc.line, 11);
  EXPECT_NE(w[0].message.find("keyframe by keyframe"), std::string::npos) << w[0].message;
}

// Mean over pixels and channels.
double mean(const Image& im) {
  double s = 0;
  for (float v : im.pixels) s += v;
  return s / double(im.pixels.size());
}

TEST(MotionBlurRender, SphereTurningAboutItsCentreLooksLikeTheStillSphere) {
  const std::string head = R"(LookAt 0 1 -5  0 0.5 0  0 1 0
Camera "perspective" "float fov" 35
Film "rgb" "integer xresolution" 32 "integer yresolution" 32
PixelFilter "box"
Sampler "independent" "integer pixelsamples" 64
Integrator "path" "integer maxdepth" 3
WorldBegin
LightSource "distant" "point3 from" [1 3 -2] "rgb L" [3 3 3]
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]
Translate 0 0.8 0
)";
  const std::string still = head + "Shape \"sphere\" \"float radius\" 0.8\n";
  const std::string turning =
      head +
      "ActiveTransform EndTime\nRotate 120 1 2 0.5\nActiveTransform All\nShape \"sphere\" \"float radius\" 0.8\n";
  const Image a1 = render(still, 1), a2 = render(still, 2), b = render(turning, 3);
  // Per pixel, b - a1 and a2 - a1 have the same variance when both images have the same
  // expectation: the standard error of the mean difference comes from the latter.
  double d = 0, e2 = 0;
  const size_t n = a1.pixels.size();
  for (size_t i = 0; i < n; ++i) {
    d += b.pixels[i] - a1.pixels[i];
    e2 += (a2.pixels[i] - a1.pixels[i]) * (a2.pixels[i] - a1.pixels[i]);
  }
  const double stderr_mean = std::sqrt(e2 / double(n)) / std::sqrt(double(n));
  EXPECT_LT(std::abs(d / double(n)), 4 * stderr_mean)
      << "still " << mean(a1) << ", turning " << mean(b) << ", standard error " << stderr_mean;
  EXPECT_GT(mean(a1), 0.05);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
