// eyetrace's "bdpt" (integrators/bdpt_integrator.h) against values from outside it:
//  - a camera inside a closed, two-sided emitting diffuse sphere (radiance Le = 1, albedo a =
//    0.5) sees exactly Le (1 + a + ... + a^d) after d bounces, whatever the estimator, so
//    "maxdepth" is checked against that sum;
//  - on scenes without specular surfaces bdpt and path estimate the same integral, so their
//    images agree in expectation: the image mean by a z-test and every pixel through the
//    squared difference of the two images against the noise both carry (from 8 independent
//    renders each), for each kind of light (area, point, spot, distant, uniform infinite),
//    with t = 1 strategies (light paths splatted through the pinhole or the thin lens), with a
//    Gaussian filter (splats spread by the filter) and without t = 1 (the eye camera);
//  - the same seed gives the same image for 1 and 2 threads and any pass size, and a render
//    stopped after a pass and resumed from its film gives the uninterrupted image;
//  - what bdpt does not do is said: media go to volpath, portals are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "../support/render_text.h"
#include "../support/sample_count.h"
#include "../support/unity_id.h"
#include "core/error.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/render_request.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string emitting_sphere(const std::string& integrator) {
  return fmt::format(
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 60\n"
      "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      "Sampler \"independent\" \"integer pixelsamples\" 64\nPixelFilter \"box\"\n"
      "Integrator {}\nWorldBegin\n"
      "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
      "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\nShape \"sphere\" \"float radius\" 2\n",
      integrator);
}

std::string error_of(const std::string& text) {
  try {
    test::render_text(text, "bdpt.pbrt");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// 16384 estimates, each between 0 and the sum of the series (< 2): the standard error of the
// mean is below 2 / sqrt(16384) / 2 = 0.008 at worst; 0.03 is about four of them.
TEST(BdptIntegrator, HonoursMaxdepthInAnEmittingSphere) {
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere("\"bdpt\" \"integer maxdepth\" 1"))), 1.5, 0.03);
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere("\"bdpt\""))), 1.96875, 0.03);  // default 5
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere("\"bdpt\" \"integer maxdepth\" 0"))), 1.0, 0.03);
}

// A convex diffuse sphere filling the view inside a uniform environment Le reflects exactly
// albedo * Le (nothing it reflects comes back to it); albedo 1 is the white furnace. Light
// paths start on the environment's disc (Light::sample_le), so every strategy is exercised.
// Every pixel estimates the same value: their spread gives the standard error, and the
// tolerance is 5 of them.
void expect_furnace(float albedo, float Le) {
  const Image img = test::render_text(fmt::format(R"(
    LookAt 0 0 -3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "independent" "integer pixelsamples" 64
    Integrator "bdpt" "integer maxdepth" 50
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "rgb L" [{0} {0} {0}]
    Material "diffuse" "rgb reflectance" [{1} {1} {1}]
    Shape "sphere" "float radius" 1
  )",
                                                  Le, albedo));
  for (int c = 0; c < 3; ++c) {
    const test::MeanAndError m = test::channel_mean_and_error(img, c);
    EXPECT_NEAR(m.mean, albedo * Le, 5 * m.std_error + 1e-4) << "albedo " << albedo << " channel " << c;
    EXPECT_LT(m.std_error, 0.02 * albedo * Le);  // the test has power
  }
}

TEST(BdptIntegrator, WhiteFurnaceMatchesEnvironment) { expect_furnace(1.f, 1.f); }
TEST(BdptIntegrator, ConvexDiffuseObjectReflectsAlbedoTimesEnvironment) { expect_furnace(0.5f, 2.f); }

TEST(BdptIntegrator, BadParametersAreNamed) {
  std::string e = error_of(emitting_sphere("\"bdpt\" \"float rrthreshold\" 0.5"));  // not pbrt-v4's bdpt's
  EXPECT_NE(e.find("bdpt.pbrt:6:"), std::string::npos) << e;
  EXPECT_NE(e.find("rrthreshold"), std::string::npos) << e;
  e = error_of(emitting_sphere("\"bdpt\" \"integer maxdepth\" -1"));
  EXPECT_NE(e.find("maxdepth"), std::string::npos) << e;
}

// The Cornell box of scenes/ without its glass sphere (a specular caustic is what path cannot
// render) and with `lights` instead of its area light when given; its front is open, so
// distant and infinite light comes in.
std::string diffuse_box(const std::string& integrator, const std::string& lights, bool keep_area_light,
                        const std::string& camera = "", const std::string& filter = "box") {
  std::ifstream in(std::string(EYETRACE_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  };
  replace("Integrator \"path\" \"integer maxdepth\" 8", "Integrator \"" + integrator + "\" \"integer maxdepth\" 5");
  replace("PixelFilter \"gaussian\"", "PixelFilter \"" + filter + "\"");
  replace("Material \"dielectric\" \"float eta\" 1.5", "Material \"diffuse\" \"rgb reflectance\" [0.5 0.6 0.7]");
  replace("WorldBegin\n", "WorldBegin\n" + lights + "\n");
  if (!keep_area_light) replace("AreaLightSource \"diffuse\" \"rgb L\" [17 12 4]", "");
  if (!camera.empty()) replace("Camera \"perspective\" \"float fov\" 40", camera);
  return s;
}

struct Renders {
  std::vector<Image> images;
};

Renders render_seeds(const std::string& text, int seeds, int spp) {
  Renders r;
  SceneDescription desc = parse_scene_string(text, "box.pbrt", ".");
  for (int k = 0; k < seeds; ++k) {
    RenderOverrides o;
    o.resolution = IVec2(24, 24);
    o.spp = spp;
    o.seed = uint64_t(100 + k);
    RenderSetup s = build_render_setup(desc, o);
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
    EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
    r.images.push_back(s.film->image());
  }
  return r;
}

// Mean over the renders of each value, and the variance of that mean (from their spread).
void mean_and_variance(const Renders& r, std::vector<double>* mean, std::vector<double>* var) {
  const size_t n = r.images[0].pixels.size(), k = r.images.size();
  mean->assign(n, 0.0);
  var->assign(n, 0.0);
  for (const Image& im : r.images)
    for (size_t i = 0; i < n; ++i) (*mean)[i] += im.pixels[i] / double(k);
  for (const Image& im : r.images)
    for (size_t i = 0; i < n; ++i) (*var)[i] += sqr(im.pixels[i] - (*mean)[i]) / double(k - 1) / double(k);
}

// bdpt and path on the same scene: 8 renders each with different seeds give per-pixel means
// and the variances of those means. Image mean: |difference| below 5 standard errors (the
// error from 8 renders: Student's t with 7 degrees of freedom exceeds 5 with probability
// 0.0016). Pixels: the mean squared difference of the two mean images over the sum of their
// variances is 1 in expectation without bias; over 1728 values its noise is a few percent
// (more with the heavy tails of light paths), so 1.5 leaves room for noise and none for a bias
// of a few standard errors per pixel. Both tolerances come from the renders' own spread, so
// the sanitizer build renders 4 samples per pixel instead of 16 (at 1, most pixels of a render
// would be 0 or one light path, too far from normal for the pixel statistic's 1.5).
void expect_same_as_path(const std::string& lights, bool keep_area_light, const std::string& camera = "",
                         const std::string& filter = "box") {
  constexpr int kSeeds = 8, kSpp = std::max(4, test::sample_count(16));
  const Renders b = render_seeds(diffuse_box("bdpt", lights, keep_area_light, camera, filter), kSeeds, kSpp);
  const Renders p = render_seeds(diffuse_box("path", lights, keep_area_light, camera, filter), kSeeds, kSpp);
  std::vector<double> mb, vb, mp, vp;
  mean_and_variance(b, &mb, &vb);
  mean_and_variance(p, &mp, &vp);
  double sq = 0, noise = 0;
  for (size_t i = 0; i < mb.size(); ++i) {
    sq += sqr(mb[i] - mp[i]);
    noise += vb[i] + vp[i];
  }
  EXPECT_LT(sq / noise, 1.5) << lights;
  auto image_means = [](const Renders& r) {
    std::vector<double> m;
    for (const Image& im : r.images) m.push_back(test::image_mean(im));
    return m;
  };
  auto mean_se = [](const std::vector<double>& v) {
    double m = 0, s2 = 0;
    for (double x : v) m += x / double(v.size());
    for (double x : v) s2 += sqr(x - m) / double(v.size() - 1);
    return std::pair(m, s2 / double(v.size()));
  };
  const auto [b_mean, b_var] = mean_se(image_means(b));
  const auto [p_mean, p_var] = mean_se(image_means(p));
  EXPECT_GT(b_mean, 0.01) << lights;  // the scene is lit
  EXPECT_LT(std::abs(b_mean - p_mean), 5.0 * std::sqrt(b_var + p_var))
      << lights << ": bdpt " << b_mean << " path " << p_mean;
}

TEST(BdptIntegrator, EqualsPathWithAnAreaLightAndAPointLight) {
  expect_same_as_path("LightSource \"point\" \"point3 from\" [0.3 0.8 0.4] \"rgb I\" [0.5 0.5 0.5]", true);
}

TEST(BdptIntegrator, EqualsPathWithSpotDistantAndInfiniteLights) {
  expect_same_as_path(
      "LightSource \"spot\" \"point3 from\" [0.5 0.9 0.5] \"point3 to\" [0.5 0 0.5] \"float coneangle\" 40 "
      "\"rgb I\" [2 2 2]\n"
      "LightSource \"distant\" \"point3 from\" [0 1 -1] \"point3 to\" [0 0 0] \"rgb L\" [1 1 1]\n"
      "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]",
      false);
}

// t = 1 through a thin lens (light paths connected to points on the lens), and with a Gaussian
// filter, whose splats reach the neighbouring pixels with its weights and whose wider samples
// beyond the film's edge t = 1 cannot make.
TEST(BdptIntegrator, EqualsPathThroughAThinLens) {
  expect_same_as_path("", true,
                      "Camera \"perspective\" \"float fov\" 40 \"float lensradius\" 0.08 "
                      "\"float focaldistance\" 2.5");
}

TEST(BdptIntegrator, EqualsPathWithAGaussianFilter) {
  expect_same_as_path("LightSource \"point\" \"point3 from\" [0.3 0.8 0.4] \"rgb I\" [0.5 0.5 0.5]", true, "",
                      "gaussian");
}

// Light paths from the image lights: the goniometric light's uniform directions and the
// projection light's cone around its frustum (tests/data/pbrt-v4's light images).
TEST(BdptIntegrator, EqualsPathWithGoniometricAndProjectionLights) {
  const std::string data = EYETRACE_SOURCE_DIR "/tests/data/pbrt-v4/";
  expect_same_as_path(
      "AttributeBegin\nTranslate 0.5 0.8 0.5\nLightSource \"goniometric\" \"string filename\" \"" + data +
          "goniometric.exr\" \"float power\" 3\nAttributeEnd\n"
          "AttributeBegin\nTranslate 0.3 0.9 0.4\nRotate 90 1 0 0\nLightSource \"projection\" \"string filename\" \"" +
          data + "projection.png\" \"float fov\" 60 \"float power\" 2\nAttributeEnd",
      false);
}

// The eye cameras have no importance function, so bdpt leaves out t = 1, whose other strategies
// need only the camera's ray: through the dispersive Navarro eye (spectral MIS over four wavelengths per sample) bdpt
// still equals path.
TEST(BdptIntegrator, EqualsPathThroughTheNavarroEye) {
  expect_same_as_path("LightSource \"point\" \"point3 from\" [0.3 0.8 0.4] \"rgb I\" [0.5 0.5 0.5]", true,
                      "Camera \"navarro\" \"float fov\" 30");
}

RenderSetup threads_setup(uint64_t seed, int spp = 6) {
  SceneDescription desc = parse_scene_string(
      diffuse_box("bdpt", "LightSource \"point\" \"point3 from\" [0.3 0.8 0.4]", true, "", "gaussian"), "b.pbrt", ".");
  RenderOverrides o;
  o.resolution = IVec2(20, 16);
  o.spp = spp;
  o.seed = seed;
  return build_render_setup(desc, o);
}

Image render_threads(int threads, int pass_samples, uint64_t seed) {
  RenderSetup s = threads_setup(seed);
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = threads;
  opts.pass_samples = pass_samples;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  return s.film->image();
}

// With t = 1 (the perspective camera), whose splats land in other tiles' pixels.
TEST(BdptIntegrator, SameSeedSameImageForAnyThreadCountAndPassSize) {
  const Image one = render_threads(1, 1, 7);
  EXPECT_TRUE(one.pixels == render_threads(2, 1, 7).pixels) << "1 and 2 threads differ";
  EXPECT_TRUE(one.pixels == render_threads(2, 4, 7).pixels) << "pass sizes 1 and 4 differ";
  EXPECT_TRUE(one.pixels == render_threads(2, 5, 7).pixels) << "pass sizes 1 and 5 differ";
  EXPECT_FALSE(one.pixels == render_threads(2, 1, 8).pixels) << "the seed has no effect";
}

// A render stopped after its first pass (light splats finish a pass before stopping, so every
// stop is at a pass's end): the film and tile progress saved there, restored into a fresh film,
// continue to the uninterrupted image.
TEST(BdptIntegrator, ResumedRenderEqualsUninterruptedOne) {
  const Image whole = render_threads(2, 2, 7);
  TileProgress tiles;
  std::vector<double> saved;
  {
    RenderSetup s = threads_setup(7);
    std::atomic<bool> stop{false};
    RenderOptions opts;
    opts.on_pass = [&](const TileProgress&) { stop = true; };
    opts.threads = 2;
    opts.pass_samples = 2;
    opts.tiles = &tiles;
    opts.stop = &stop;
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
    saved = s.film->accumulators();
  }
  EXPECT_EQ(tiles.min_done(), 2);
  EXPECT_EQ(tiles.max_done(), 2);
  RenderSetup s = threads_setup(7);
  s.film->restore(saved, 0);
  RenderOptions opts;
  opts.threads = 1;
  opts.pass_samples = 3;
  opts.tiles = &tiles;
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_TRUE(s.film->image().pixels == whole.pixels) << "resumed and uninterrupted renders differ";
}

// A spectral film takes t = 1's splats in its buckets too: on the caustic scene (the caustic
// carried by t = 1 alone) its R, G, B are those of the rgb film, and its buckets gain from t = 1
// what its luminance gains (to within the noise: 10 % of the gain).
// A stop requested while a pass runs (from another thread, 20 ms in: usually inside the first
// of two passes of 16 samples) still leaves every tile at the same sample count, the pass's end,
// and the resumed render equals the uninterrupted one (whenever the stop landed).
TEST(BdptIntegrator, StopDuringAPassFinishesItAndResumesExactly) {
  auto render = [](TileProgress* tiles, const std::atomic<bool>* stop, const std::vector<double>* restore,
                   std::vector<double>* saved) {
    RenderSetup s = threads_setup(9, 32);
    if (restore) s.film->restore(*restore, 0);
    RenderOptions opts;
    opts.threads = 2;
    opts.pass_samples = 16;
    opts.tiles = tiles;
    opts.stop = stop;
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
    if (saved) *saved = s.film->accumulators();
    return s.film->image();
  };
  const Image whole = render(nullptr, nullptr, nullptr, nullptr);
  TileProgress tiles;
  std::atomic<bool> stop{false};
  std::vector<double> saved;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    stop = true;
  });
  render(&tiles, &stop, nullptr, &saved);
  stopper.join();
  EXPECT_EQ(tiles.min_done(), tiles.max_done());
  EXPECT_EQ(tiles.min_done() % 16, 0);
  EXPECT_TRUE(render(&tiles, nullptr, &saved, nullptr).pixels == whole.pixels) << "stopped at " << tiles.min_done();
}

TEST(BdptIntegrator, SpectralFilmBucketsTakeTheSplats) {
  std::ifstream in(std::string(EYETRACE_SOURCE_DIR) + "/tests/data/pbrt-v4/bdpt-caustic.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string rgb = ss.str();
  auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
  };
  const std::string spectral = replaced(rgb, "Film \"rgb\"", "Film \"spectral\" \"integer nbuckets\" 3");
  const std::string lt = "\"integer maxdepth\" 5";
  auto render = [](const std::string& text) {
    SceneDescription desc = parse_scene_string(text, "caustic.pbrt", ".");
    RenderOverrides o;
    o.resolution = IVec2(24, 24);
    o.spp = 16;
    o.seed = 3;
    RenderSetup s = build_render_setup(desc, o);
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
    EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
    return s.film->image();
  };
  const Image on = render(spectral), off = render(replaced(spectral, lt, lt + " \"bool lighttracing\" false"));
  const Image plain = render(rgb);
  ASSERT_EQ(on.channels, 6);
  double rgb_on = 0, rgb_off = 0, buckets_on = 0, buckets_off = 0;
  for (size_t p = 0; p < size_t(on.width) * on.height; ++p) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(on.pixels[p * 6 + c], plain.pixels[p * 3 + c]) << "pixel " << p << " channel " << c;
      rgb_on += on.pixels[p * 6 + c];
      rgb_off += off.pixels[p * 6 + c];
    }
    for (int b = 3; b < 6; ++b) {
      buckets_on += on.pixels[p * 6 + b];
      buckets_off += off.pixels[p * 6 + b];
    }
  }
  const double gain_rgb = rgb_on / rgb_off - 1, gain_buckets = buckets_on / buckets_off - 1;
  EXPECT_GT(gain_rgb, 0.05);
  EXPECT_NEAR(gain_buckets, gain_rgb, 0.1 * gain_rgb) << "rgb " << gain_rgb << " buckets " << gain_buckets;
}

// A crop window renders one light path per camera sample of the crop, while importance covers
// the full film: the splats are scaled by the full film's pixels over the crop's. On the caustic
// scene (t = 1 carries the caustic and part of the floor's light), a crop of a quarter of the
// image has the mean the full image has there (unscaled splats: measured 23 % less), within 3 %
// (the region mean's spread over 5 seeds of the full render: 0.7 % relative standard deviation).
TEST(BdptIntegrator, CropWindowKeepsTheSplatsEnergy) {
  std::ifstream in(std::string(EYETRACE_SOURCE_DIR) + "/tests/data/pbrt-v4/bdpt-caustic.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  auto render = [&](const std::string& crop, uint64_t seed) {
    SceneDescription desc = parse_scene_string(ss.str(), "caustic.pbrt", ".");
    RenderOverrides o;
    o.resolution = IVec2(32, 32);
    o.spp = 64;
    o.seed = seed;
    if (!crop.empty()) o.crop = parse_crop(crop);
    RenderSetup s = build_render_setup(desc, o);
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
    return s.film->image();
  };
  const Image full = render("", 1), crop = render("0.25,0.75,0.5,1", 2);
  ASSERT_EQ(crop.width, 16);
  ASSERT_EQ(crop.height, 16);
  double a = 0, b = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) {
        a += full.pixels[(size_t(y + 16) * 32 + size_t(x + 8)) * 3 + size_t(c)];
        b += crop.pixels[(size_t(y) * 16 + size_t(x)) * 3 + size_t(c)];
      }
  EXPECT_NEAR(b / a, 1.0, 0.03) << "full " << a << " crop " << b;
}

TEST(BdptIntegrator, SceneWithMediaIsRenderedByVolpath) {
  const std::string text =
      "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
      "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      "Sampler \"independent\" \"integer pixelsamples\" 4\nIntegrator \"bdpt\"\nWorldBegin\n"
      "LightSource \"point\" \"point3 from\" [0 2 -2]\n"
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.1 0.1] "
      "\"rgb sigma_s\" [0.5 0.5 0.5]\n"
      "MediumInterface \"fog\" \"\"\nMaterial \"interface\"\nShape \"sphere\" \"float radius\" 1\n";
  SceneDescription desc = parse_scene_string(text, "fog.pbrt", ".");
  RenderSetup s = build_render_setup(desc, {});
  EXPECT_NE(s.integrator->to_string().find("volpath"), std::string::npos) << s.integrator->to_string();
}

TEST(BdptIntegrator, PortalLightIsRefusedWithTheIntegratorsPlace) {
  const std::string e = error_of(
      "LookAt 0 0 0  0 1 0  0 0 1\nCamera \"perspective\"\n"
      "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      "Integrator \"bdpt\"\nWorldBegin\n"
      "LightSource \"infinite\" \"point3 portal\" [-0.4 1 0.6  0.4 1 0.6  0.4 1 1.4  -0.4 1 1.4]\n"
      "Material \"diffuse\"\nShape \"sphere\" \"float radius\" 0.2\n");
  EXPECT_NE(e.find("bdpt.pbrt:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("portal"), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
