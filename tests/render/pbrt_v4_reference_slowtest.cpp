// eyetrace against pbrt-v4 itself, feature by feature: each scene of tests/data/pbrt-v4/
// (bump mapping on diffuse, conductor and dielectric, the bilerp and imagemap textures, the mix material,
// diffusetransmission, thindielectric, partial cylinders, curves, the directionmix, noise and dots
// textures, the paddedsobol sampler, coatedconductor, hair, measured, a camera sensor with white balance and ISO,
// maxcomponentvalue, the gbuffer film's channels, motion blur, the grid media uniformgrid,
// cloud, rgbgrid and nanovdb, the orthographic and spherical cameras, the sinc filter, the
// goniometric and projection lights, the bdpt and sppm integrators) is rendered here by eyetrace with two seeds and
// compared with the two images pbrt-v4 rendered of the same scene text with two seeds (tests/data/pbrt-v4/PROVENANCE:
// pbrt-v4's commit, build and command). The scenes name everything whose default could differ (box pixel filter, the
// independent sampler, the path integrator and its depth, rgb film at ISO 100 and 1 s unless the scene is about the
// film, fp32).
//
// Two assertions per scene:
// - Each channel's image mean is within 1 % of pbrt-v4's (the issue's tolerance; the means'
//   own noise, printed, is about 0.1 % at these sample counts).
// - The relative MSE between the two renderers' images, mean over pixels of
//   sum_c (a - b)^2 / (b^2 + 0.01) with a, b the means of each renderer's two seeds, is no more
//   than the noise of the two sample counts explains. With a1, a2 (b1, b2) independent renders
//   of the same expectation, E[(a1 - a2)^2] / 4 is the variance of a = (a1 + a2) / 2, so under
//   "same expectation" the per-pixel term
//     d = sum_c [(a - b)^2 - ((a1 - a2)^2 + (b1 - b2)^2) / 4] / (b^2 + 0.01)
//   has mean 0 (to first order in b's noise, which enters the weight only), and pixels are
//   independent (independent sampler, box filter of radius 1/2: each sample lands in one
//   pixel). The test asserts mean(d) < 4 standard errors of mean(d) over the 4096 pixels:
//   one-sided, a false failure with probability about 3e-5 under the central limit theorem.
//   A bias b' in every pixel adds b'^2 / (b^2 + 0.01) to mean(d): the last test shows what size
//   of change is caught.
// Three differences are asserted at their size. pbrt-v4 swaps the dots texture's inside and
// outside (a pbrt-v4 bug, swap_dots_inside_outside). eyetrace's coatedconductor is closed-form
// and less saturated than pbrt-v4's random walk for a rough coat on a rough metal. And
// eyetrace's light-leak guard
// (src/materials/local_bsdf.h) drops directions that the geometric and the shading normal put on
// different sides, pbrt-v4 keeps them; with a bump map under a sky that darkens eyetrace by a
// known amount (bump-sky.pbrt, docs/scene-format.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/unity_id.h"
#include "nanovdb_smoke.h"
#include "render/film.h"
#include "render/image_io.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::string kDataDir = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/pbrt-v4/";
// eyetrace's samples per pixel per seed (pbrt-v4's are in PROVENANCE: 4096 per seed, so its
// images add a 32nd of eyetrace's variance).
constexpr int kSpp = 128;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// pbrt-v4 (5f7a606) paints a dots texture's "inside" outside the dots and its "outside" inside:
// FloatDotsTexture::Create and SpectrumDotsTexture::Create pass (inside, outside) to constructors
// that take (outsideDot, insideDot) (src/pbrt/textures.cpp and textures.h). eyetrace follows the
// parameter names; to compare the rest of a scene with dots, eyetrace renders its text with the
// two names exchanged.
std::string swap_dots_inside_outside(std::string text) {
  const std::string inside = "\"rgb inside\"", outside = "\"rgb outside\"", mark = "\"rgb @@\"";
  for (auto [from, to] : {std::pair{inside, mark}, std::pair{outside, inside}, std::pair{mark, outside}})
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  return text;
}

// `remove`, when not empty, is cut out of the scene text (once) before it is rendered.
Image render_eyetrace(const std::string& scene, uint64_t seed, bool swap_dots, const std::string& remove = "") {
  std::string text = read_text(kDataDir + scene + ".pbrt");
  if (swap_dots) text = swap_dots_inside_outside(text);
  if (!remove.empty()) {
    const size_t at = text.find(remove);
    EXPECT_NE(at, std::string::npos) << remove;
    if (at != std::string::npos) text.erase(at, remove.size());
  }
  // The NanoVDB volume is written by code (nanovdb_smoke.h), into the build tree.
  const std::string nvdb = "\"nanovdb-smoke.nvdb\"";
  if (const size_t at = text.find(nvdb); at != std::string::npos) {
    const std::string path = std::string(EYETRACE_BINARY_DIR) + "/nanovdb-smoke.nvdb";
    test::write_nanovdb_smoke(path);
    text.replace(at, nvdb.size(), "\"" + path + "\"");
  }
  SceneDescription desc = parse_scene_string(text, kDataDir + scene + ".pbrt", kDataDir);
  RenderOverrides overrides;
  overrides.spp = kSpp;
  overrides.seed = seed;
  RenderSetup s = build_render_setup(desc, overrides);
  RenderCounters counters;
  RenderOptions options;
  options.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, options, counters);
  return s.film->image();
}

// One scene's four images: eyetrace's two seeds, pbrt-v4's two (cached: the last test reuses one).
struct ImagePairs {
  Image a1, a2, b1, b2;
};

// `reference` names pbrt-v4's images when they are another scene's (the same picture made with
// a sampler whose pbrt-v4 tables the oracle lacks); by default the scene's own.
const ImagePairs& images(const std::string& scene, bool swap_dots = false, std::string reference = "") {
  if (reference.empty()) reference = scene;
  static std::map<std::pair<std::string, bool>, ImagePairs> cache;
  auto it = cache.find({scene, swap_dots});
  if (it == cache.end()) {
    ImagePairs p{render_eyetrace(scene, 1, swap_dots), render_eyetrace(scene, 2, swap_dots),
                 read_image(kDataDir + reference + "-seed1.exr"), read_image(kDataDir + reference + "-seed2.exr")};
    it = cache.emplace(std::pair{scene, swap_dots}, std::move(p)).first;
  }
  return it->second;
}

struct Comparison {
  double mean_a[3] = {0, 0, 0}, mean_b[3] = {0, 0, 0};
  double mean_sigma[3] = {0, 0, 0};  // standard error of mean_a - mean_b, from the seed pairs
  double rel_mse = 0, expected_rel_mse = 0, excess_stderr = 0;
};

// `scale` multiplies eyetrace's images (1 for the comparison itself) and `add`, when given, is
// added to them (per pixel and channel).
Comparison compare(const ImagePairs& p, double scale, const std::vector<double>* add = nullptr) {
  const size_t n = size_t(p.b1.width) * p.b1.height;
  Comparison c;
  double sum_d = 0, sum_d2 = 0;
  for (size_t i = 0; i < n; ++i) {
    double d = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const size_t k = i * 3 + ch;
      const double offset = add ? (*add)[k] : 0.0;
      const double a1 = scale * p.a1.pixels[k] + offset, a2 = scale * p.a2.pixels[k] + offset;
      const double b1 = p.b1.pixels[k], b2 = p.b2.pixels[k];
      const double a = 0.5 * (a1 + a2), b = 0.5 * (b1 + b2);
      const double noise = 0.25 * ((a1 - a2) * (a1 - a2) + (b1 - b2) * (b1 - b2));
      const double w = 1.0 / (b * b + 0.01);
      c.mean_a[ch] += a;
      c.mean_b[ch] += b;
      c.mean_sigma[ch] += noise;
      c.rel_mse += w * (a - b) * (a - b);
      c.expected_rel_mse += w * noise;
      d += w * ((a - b) * (a - b) - noise);
    }
    sum_d += d;
    sum_d2 += d * d;
  }
  for (int ch = 0; ch < 3; ++ch) {
    c.mean_a[ch] /= double(n);
    c.mean_b[ch] /= double(n);
    c.mean_sigma[ch] = std::sqrt(c.mean_sigma[ch]) / double(n);
  }
  c.rel_mse /= double(n);
  c.expected_rel_mse /= double(n);
  const double mean_d = sum_d / double(n);
  c.excess_stderr = std::sqrt((sum_d2 / double(n) - mean_d * mean_d) / double(n - 1));
  return c;
}

void expect_matches_pbrt_v4(const std::string& scene, const std::vector<double>* add = nullptr, bool swap_dots = false,
                            const std::string& reference = "") {
  const ImagePairs& p = images(scene, swap_dots, reference);
  for (const Image* im : {&p.a1, &p.a2, &p.b1, &p.b2}) {
    ASSERT_EQ(im->width, 64) << scene;
    ASSERT_EQ(im->height, 64) << scene;
    ASSERT_EQ(im->channels, 3) << scene;
    for (float v : im->pixels) ASSERT_TRUE(std::isfinite(v)) << scene;
  }
  const Comparison c = compare(p, 1.0, add);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(c.mean_a[ch], c.mean_b[ch], 0.01 * c.mean_b[ch])
        << scene << " channel " << ch << ": eyetrace " << c.mean_a[ch] << ", pbrt-v4 " << c.mean_b[ch]
        << " (standard error of the difference " << c.mean_sigma[ch] << ")";
  }
  EXPECT_LT(c.rel_mse - c.expected_rel_mse, 4 * c.excess_stderr)
      << scene << ": relative MSE " << c.rel_mse << ", the seeds' noise explains " << c.expected_rel_mse;
  std::printf(
      "%-20s means eyetrace/pbrt-v4 %.5f %.5f %.5f (sigma %.5f %.5f %.5f); relMSE %.3e, noise %.3e, "
      "excess %.2f sigma\n",
      scene.c_str(), c.mean_a[0] / c.mean_b[0], c.mean_a[1] / c.mean_b[1], c.mean_a[2] / c.mean_b[2],
      c.mean_sigma[0] / c.mean_b[0], c.mean_sigma[1] / c.mean_b[1], c.mean_sigma[2] / c.mean_b[2], c.rel_mse,
      c.expected_rel_mse, (c.rel_mse - c.expected_rel_mse) / c.excess_stderr);
}

TEST(PbrtV4Reference, BumpMapOnDiffuseAndConductorPlanes) { expect_matches_pbrt_v4("bump"); }
TEST(PbrtV4Reference, BumpMapOnADielectricBeforeAnEmitter) { expect_matches_pbrt_v4("bump-dielectric"); }
TEST(PbrtV4Reference, BilerpTextureAsReflectance) { expect_matches_pbrt_v4("bilerp"); }
// An 8-bit PNG whose sides are not powers of two, bilinear with repeat and point with clamp:
// eyetrace's MIP map (render/mipmap.h) resizes and decodes it as pbrt-v4 does.
TEST(PbrtV4Reference, ImagemapPngOfNonPowerOfTwoSizeBilinearAndPoint) { expect_matches_pbrt_v4("imagemap"); }
TEST(PbrtV4Reference, MixMaterialConstantAndTexturedAmount) { expect_matches_pbrt_v4("mix"); }
TEST(PbrtV4Reference, DiffuseTransmissionLitFromBothSides) { expect_matches_pbrt_v4("diffusetransmission"); }
TEST(PbrtV4Reference, ThinDielectricPaneBeforeAnEmitter) { expect_matches_pbrt_v4("thindielectric"); }

TEST(PbrtV4Reference, PartialCylindersSeenFromOutsideAndInsideAndAsAnAreaLight) { expect_matches_pbrt_v4("cylinder"); }
TEST(PbrtV4Reference, DirectionMixTextureInWorldAndRotatedTextureSpace) { expect_matches_pbrt_v4("directionmix"); }
TEST(PbrtV4Reference, PaddedSobolSamplerOnTheMixScene) { expect_matches_pbrt_v4("mix-paddedsobol"); }
TEST(PbrtV4Reference, AreaLightsOnCutOutShapesAndAnInvisibleEmitter) { expect_matches_pbrt_v4("alpha-light"); }
// Loop subdivision: eyetrace's boundary limit mask (1/6, 2/3, 1/6) moves the open grid's boundary
// vertices by a fraction of a percent of their spacing from pbrt-v4's (1/5, 3/5, 1/5): within the noise.
TEST(PbrtV4Reference, LoopSubdivisionClosedAndWithABoundary) { expect_matches_pbrt_v4("loopsubdiv"); }
// An image sky seen only through a window's portal (pbrt-v4 samples it in its own parameterisation).
TEST(PbrtV4Reference, PortalOnAWindowOfAClosedRoom) { expect_matches_pbrt_v4("portal"); }
// The camera's shutter interval (0.4 s) with ISO 200 sets the film's exposure, as pbrt-v4 reads it.
TEST(PbrtV4Reference, CameraShutterIntervalIsTheExposureTime) { expect_matches_pbrt_v4("shutter"); }
// Motion blur: a moving, growing sphere (an animated shape), a turning box (an animated
// ObjectInstance) and a panning camera, with the shutter reaching past the end time.
TEST(PbrtV4Reference, MotionBlurOfShapeInstanceAndCameraPastTheEndTime) { expect_matches_pbrt_v4("motion"); }
// pbrt-v4's bidirectional path tracer against eyetrace's (both with t = 1 strategies; the
// image does not depend on them in expectation, here without specular surfaces).
TEST(PbrtV4Reference, BdptIntegratorInABoxLitFromAbove) { expect_matches_pbrt_v4("bdpt"); }
// The same with light paths from a point, a spot and a distant light (Light::sample_le).
TEST(PbrtV4Reference, BdptIntegratorWithPointSpotAndDistantLights) { expect_matches_pbrt_v4("bdpt-lights"); }
// bdpt's t = 1 strategies: the caustic a glass sphere focuses from a point light onto a diffuse
// floor, seen directly, which only light paths connected to the camera carry.
TEST(PbrtV4Reference, BdptCausticOfAPointLightSeenDirectly) { expect_matches_pbrt_v4("bdpt-caustic"); }
// Stochastic progressive photon mapping, at the same radius, iterations (128: the test's samples
// per pixel, and pbrt-v4's --spp) and photons on both sides, so that both carry the same
// finite-radius bias. Pixels share photons, so they are not independent as the relative-MSE
// check assumes; the check passes with room (measured excess 1.4 and 0.5 standard errors).
TEST(PbrtV4Reference, SppmInTheBoxLitFromAbove) { expect_matches_pbrt_v4("sppm-box"); }
// The caustic a glass sphere focuses from a point light, which only photons carry.
TEST(PbrtV4Reference, SppmCausticOfAPointLightThroughAGlassSphere) { expect_matches_pbrt_v4("sppm-caustic"); }
// pbrt-v4's pmj02bn tables are not in the oracle's source snapshot (PROVENANCE): eyetrace's
// pmj02bn render of the mix scene is compared with pbrt-v4's independent-sampler images of it.
TEST(PbrtV4Reference, Pmj02bnSamplerOnTheMixScene) { expect_matches_pbrt_v4("mix-pmj02bn", nullptr, false, "mix"); }
TEST(PbrtV4Reference, CameraSensorWithWhiteBalanceAndIso) { expect_matches_pbrt_v4("sensor"); }
// maxcomponentvalue makes a pixel's mean depend on how its samples are distributed (a biased
// estimate); the scene clamps only samples whose value depends on their wavelengths alone (an
// emitter seen directly), which both renderers draw from the same density, so the means must
// agree as for any other scene. The clamp matters there: without it eyetrace's mean red is
// more than twice pbrt-v4's (MaxComponentValueIsWhatMakesTheClampSceneMatch).
TEST(PbrtV4Reference, MaxComponentValueClampsEverySampleOfABrightEmitter) {
  expect_matches_pbrt_v4("maxcomponentvalue");
}
TEST(PbrtV4Reference, CoatedConductorSmoothCoatOnSmoothMetal) { expect_matches_pbrt_v4("coatedconductor-smooth"); }
TEST(PbrtV4Reference, HairOnStripsWithMelaninReflectanceAndSigmaA) { expect_matches_pbrt_v4("hair"); }
// The measured material on two spheres sharing one RGL tensor file (tests/data/measured: a
// GGX conductor tabulated by tools/make_measured_bsdf), under a quad light and a sky.
TEST(PbrtV4Reference, MeasuredMaterialFromAnRglTensorFile) { expect_matches_pbrt_v4("measured"); }
// A flat Bezier curve of tapering width, a wide "cylinder" B-spline and a twisting quadratic
// "ribbon" over a floor, lit from the side (their shadows too): pbrt-v4's ray-facing bands,
// its bent cylinder normal and its narrowed ribbon, as shapes/curve.h reproduces them.
TEST(PbrtV4Reference, CurvesFlatCylinderAndRibbonOverAFloor) { expect_matches_pbrt_v4("curves"); }
// Integrator "volpath": the camera in chromatic fog, an interface sphere of denser fog, a diffuse
// floor and sphere and an area light. eyetrace's shadow rays carry the exact transmittance where
// pbrt-v4 ratio-tracks it: the same expectation, different noise.
TEST(PbrtV4Reference, VolpathCameraInChromaticFogWithAnInterfaceSphereOfDenserFog) { expect_matches_pbrt_v4("fog"); }
// The same with the denser fog emitting: pbrt-v4 reads "Le" as an area light's "L" (normalised
// by its luminance), and weights emission at collisions by r_e.
TEST(PbrtV4Reference, VolpathEmissiveMediumInsideAnInterfaceSphere) { expect_matches_pbrt_v4("fog-glow"); }
// The subsurface material (photon beam diffusion BSSRDF) on two spheres: a named measured
// medium ("Skin1", scaled) under a smooth boundary, and "reflectance" + "mfp" with g 0.5 under a
// rough one; Integrator "volpath" as pbrt-v4 needs (its "path" ignores BSSRDFs).
TEST(PbrtV4Reference, SubsurfaceNamedMediumAndReflectanceWithRoughBoundary) { expect_matches_pbrt_v4("subsurface"); }
// Heterogeneous media, delta-tracked against majorant grids, shadow rays ratio-tracked: a
// rotated "uniformgrid" density ramp with chromatic scattering under an area light; pbrt-v4's
// procedural "cloud" (its Perlin noise, placed by a transform); an emissive uniformgrid
// (temperature grid: blackbody emission times an Lescale grid, no lights); an "rgbgrid" with
// RGB sigma_a, sigma_s and Le grids; a "nanovdb" volume with density and temperature grids.
TEST(PbrtV4Reference, VolpathUniformGridDensityRampUnderAnAreaLight) { expect_matches_pbrt_v4("grid-ramp"); }
TEST(PbrtV4Reference, VolpathProceduralCloudMedium) { expect_matches_pbrt_v4("cloud"); }
TEST(PbrtV4Reference, VolpathUniformGridTemperatureEmission) { expect_matches_pbrt_v4("grid-fire"); }
TEST(PbrtV4Reference, VolpathRgbGridWithEmission) { expect_matches_pbrt_v4("rgbgrid"); }
TEST(PbrtV4Reference, VolpathNanoVDBDensityAndTemperature) { expect_matches_pbrt_v4("nanovdb"); }

// The cameras, filter and lights that were pbrt-v4's last unsupported plugins: an orthographic
// camera with an off-centre screen window and pbrt-v4's thin lens; the spherical camera in both
// mappings; the windowed sinc filter at its defaults (signed sample weights; pixels stay
// independent, each sample landing in one pixel); a goniometric light from an RGB equal-area
// image with "power" and "scale"; a projection light from an 8-bit sRGB PNG with "power" and
// "scale" (tests/data/pbrt-v4/make_light_images.py made both images).
TEST(PbrtV4Reference, OrthographicCameraWithScreenWindowAndThinLens) { expect_matches_pbrt_v4("orthographic"); }
TEST(PbrtV4Reference, SphericalCameraEqualArea) { expect_matches_pbrt_v4("spherical"); }
TEST(PbrtV4Reference, SphericalCameraEquirectangular) { expect_matches_pbrt_v4("spherical-equirectangular"); }
TEST(PbrtV4Reference, SincPixelFilterAtItsDefaults) { expect_matches_pbrt_v4("sinc"); }
TEST(PbrtV4Reference, GoniometricLightFromAnRgbEqualAreaImage) { expect_matches_pbrt_v4("goniometric"); }
TEST(PbrtV4Reference, ProjectionLightFromAnSrgbPng) { expect_matches_pbrt_v4("projection"); }

// fbm, wrinkled, windy (as mix amounts), dots and marble. The scene's scales keep every noise
// octave in pbrt-v4 too (noise.pbrt). pbrt-v4's dots paint "inside" and "outside" the other way
// round (swap_dots_inside_outside): with the names exchanged eyetrace matches; with the text as
// written the dots quad alone differs, and by more than the tolerance.
TEST(PbrtV4Reference, NoiseTexturesAndDotsWithPbrtV4sInsideOutsideSwap) {
  expect_matches_pbrt_v4("noise", nullptr, /*swap_dots=*/true);
  const Comparison c = compare(images("noise"), 1.0);
  // The dots' colours, (0.8, 0.2, 0.1) and (0.2, 0.3, 0.6), differ most in red and blue.
  for (int ch : {0, 2}) EXPECT_GT(std::abs(c.mean_a[ch] / c.mean_b[ch] - 1), 0.03) << ch;
  std::printf("noise, dots as written: means eyetrace/pbrt-v4 %.4f %.4f %.4f\n", c.mean_a[0] / c.mean_b[0],
              c.mean_a[1] / c.mean_b[1], c.mean_a[2] / c.mean_b[2]);
}

// A rough coat on a rough metal: eyetrace's closed-form model (coated_conductor_bxdf.h) is not
// pbrt-v4's random walk, which also follows light bouncing between coat and metal (each bounce
// tints it by the metal again). Not a match on purpose: the luminance agrees (within 0.3 %) but
// eyetrace is less saturated, red 3.3 % lower and blue 6.1 % higher, most at grazing views. The
// test prints the difference and checks it stays the size documented in docs/scene-format.md
// (each channel's mean ratio within 1 % of the measured one; their noise is 0.1 to 0.15 %).
TEST(PbrtV4Reference, CoatedConductorRoughCoatOnRoughMetalDiffersByTheDocumentedAmount) {
  const ImagePairs& p = images("coatedconductor-rough");
  for (const Image* im : {&p.a1, &p.a2, &p.b1, &p.b2})
    for (float v : im->pixels) ASSERT_TRUE(std::isfinite(v));
  const Comparison c = compare(p, 1.0);
  const double documented[3] = {0.967, 1.018, 1.061};  // measured, 2 x 128 against 2 x 4096
  for (int ch = 0; ch < 3; ++ch) {
    const double ratio = c.mean_a[ch] / c.mean_b[ch];
    std::printf("coatedconductor-rough channel %d: eyetrace/pbrt-v4 %.4f (sigma %.4f)\n", ch, ratio,
                c.mean_sigma[ch] / c.mean_b[ch]);
    EXPECT_NEAR(ratio, documented[ch], 0.01) << ch;
  }
}

// What eyetrace's light-leak guard takes from bump-sky.pbrt, per pixel: the diffuse plane
// (reflectance 0.5, 3 x 3 units, (u, v) from 0 to 1) displaced by d = 0.9 u (1 - 2 v) has the
// bumped normal ~ (-a, -b, 3) / |.| against the geometric (0, 0, 1), a = dd/du = 0.9 (1 - 2 v),
// b = dd/dv = -1.8 u (any sign convention gives the same tilt theta). The part of the sky (0.2)
// below the plane, weighted by the cosine to the bumped normal, is (1 - cos theta) / 2 of the
// hemisphere (a tilted surface's sky view factor is (1 + cos theta) / 2), and pbrt-v4 reflects
// it: 0.5 * 0.2 * (1 - cos theta) / 2 more. Averaged over 8 x 8 points of each pixel; pbrt-v4's
// camera (LookAt from +z, up +y) puts world +x at the image's left.
std::vector<double> bump_sky_guard_term() {
  const int res = 64, sub = 8;
  const double half_width = 5.0 * std::tan(15.0 * 3.14159265358979 / 180.0);  // fov 30 at distance 5
  std::vector<double> add(size_t(res) * res * 3);
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      double sum = 0;
      for (int sj = 0; sj < sub; ++sj)
        for (int si = 0; si < sub; ++si) {
          const double x = -(-1.0 + 2.0 * (i + (si + 0.5) / sub) / res) * half_width;
          const double y = (1.0 - 2.0 * (j + (sj + 0.5) / sub) / res) * half_width;
          const double u = (x + 1.5) / 3.0, v = (y + 1.5) / 3.0;
          const double a = 0.9 * (1.0 - 2.0 * v), b = -1.8 * u;
          const double cos_theta = 3.0 / std::sqrt(9.0 + a * a + b * b);
          sum += 0.5 * 0.2 * (1.0 - cos_theta) / 2.0;
        }
      for (int ch = 0; ch < 3; ++ch) add[(size_t(j) * res + i) * 3 + ch] = sum / (sub * sub);
    }
  return add;
}

TEST(PbrtV4Reference, BumpMapUnderASkyDiffersByTheLightLeakGuard) {
  const std::vector<double> add = bump_sky_guard_term();
  expect_matches_pbrt_v4("bump-sky", &add);
  // Without the guard's share eyetrace is darker than pbrt-v4 beyond the 1 % tolerance (the
  // relative MSE alone, at these sample counts, would not see it: 1.5 standard errors).
  const Comparison c = compare(images("bump-sky"), 1.0);
  for (int ch = 0; ch < 3; ++ch) EXPECT_LT(c.mean_a[ch], 0.99 * c.mean_b[ch]) << ch;
}

// The comparison can fail: eyetrace's bump image made 2 % brighter misses both criteria.
TEST(PbrtV4Reference, ATwoPercentChangeIsCaught) {
  const Comparison c = compare(images("bump"), 1.02);
  for (int ch = 0; ch < 3; ++ch) EXPECT_GT(std::abs(c.mean_a[ch] / c.mean_b[ch] - 1), 0.01) << ch;
  EXPECT_GT(c.rel_mse - c.expected_rel_mse, 4 * c.excess_stderr);
}

// The named channels of `im`, in that order (an empty name: a channel of zeros).
Image select_channels(const Image& im, const std::vector<std::string>& names) {
  std::map<std::string, int> at;
  for (int c = 0; c < im.channels; ++c)
    at[im.channel_names.empty() ? std::string(1, "RGB"[c]) : im.channel_names[c]] = c;
  Image out;
  out.width = im.width;
  out.height = im.height;
  out.channels = int(names.size());
  out.channel_names = names;
  out.pixels.assign(size_t(out.width) * out.height * out.channels, 0.f);
  for (int c = 0; c < out.channels; ++c) {
    EXPECT_TRUE(at.count(names[c])) << names[c];
    if (!at.count(names[c])) continue;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) out.at(x, y, c) = im.at(x, y, at[names[c]]);
  }
  return out;
}

// The gbuffer film: R, G, B compared as every scene's, and the auxiliary channels pbrt-v4
// writes and eyetrace too (all but Variance, which is of other quantities, render/gbuffer.h)
// by their image means: within 1 % of the channel's mean magnitude. Positions, normals and
// (u, v) vary only within a pixel, so their means carry almost no noise; the albedo is pbrt-v4's
// 16-sample estimate in both, exact for diffuse surfaces, its colour a Monte Carlo estimate.
TEST(PbrtV4Reference, GBufferFilmAuxiliaryChannels) {
  const std::vector<std::string> aux = {"Albedo.R", "Albedo.G", "Albedo.B", "P.X",  "P.Y",  "P.Z",  "dzdx", "dzdy",
                                        "N.X",      "N.Y",      "N.Z",      "Ns.X", "Ns.Y", "Ns.Z", "u",    "v"};
  const Image a = render_eyetrace("gbuffer", 1, false), b = read_image(kDataDir + "gbuffer-seed1.exr");
  const Image rgb_a1 = select_channels(a, {"R", "G", "B"});
  ImagePairs p{rgb_a1, select_channels(render_eyetrace("gbuffer", 2, false), {"R", "G", "B"}),
               select_channels(b, {"R", "G", "B"}),
               select_channels(read_image(kDataDir + "gbuffer-seed2.exr"), {"R", "G", "B"})};
  const Comparison c = compare(p, 1.0);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(c.mean_a[ch], c.mean_b[ch], 0.01 * c.mean_b[ch]) << ch;
  EXPECT_LT(c.rel_mse - c.expected_rel_mse, 4 * c.excess_stderr);
  const Image xa = select_channels(a, aux), xb = select_channels(b, aux);
  for (int ch = 0; ch < int(aux.size()); ++ch) {
    double ma = 0, mb = 0, mag = 0;
    for (int y = 0; y < xa.height; ++y)
      for (int x = 0; x < xa.width; ++x) {
        ma += xa.at(x, y, ch);
        mb += xb.at(x, y, ch);
        mag += std::abs(xb.at(x, y, ch));
      }
    const double n = double(xa.width) * xa.height;
    EXPECT_NEAR(ma / n, mb / n, 0.01 * mag / n) << aux[ch];
    std::printf("gbuffer %-9s eyetrace %9.5f pbrt-v4 %9.5f (difference %.2e of the mean magnitude)\n", aux[ch].c_str(),
                ma / n, mb / n, std::abs(ma - mb) / mag);
  }
}

TEST(PbrtV4Reference, MaxComponentValueIsWhatMakesTheClampSceneMatch) {
  const Image unclamped = render_eyetrace("maxcomponentvalue", 1, false, "\"float maxcomponentvalue\" 1.5");
  const Image& pbrt = images("maxcomponentvalue").b1;
  double a = 0, b = 0;
  for (size_t i = 0; i < pbrt.pixels.size(); i += 3) {
    a += unclamped.pixels[i];
    b += pbrt.pixels[i];
  }
  EXPECT_GT(a / b, 2.0);
  std::printf("maxcomponentvalue scene without the clamp: mean red %.3f times pbrt-v4's\n", a / b);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
