// A dispersive eye's wavelengths traced apart (`"string dispersionsampling" "paths"`: each
// wavelength's own camera ray and path) against the same wavelengths
// sharing the hero's path by spectral MIS (`"mis"`): two estimators of the same image built
// from different techniques, so their agreement is a check of each. The images of several
// seeds give each block of pixels a mean and a standard error; every block and channel must
// agree within 4.5 standard errors (for 2 x 15 x 3 comparisons, a false alarm has probability
// about 6e-4). And "auto" must pick MIS, except paths with a box filter under adaptive sampling
// (docs/spectral.md, "Wavelength paths").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/lit_sphere_world.h"
#include "../support/render_text.h"
#include "../support/sample_count.h"
#include "../support/unity_id.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// A lit sphere on a floor (black sky), through the dispersive Navarro eye at a 6 mm pupil,
// where blue and red land pixels apart; 40x24 pixels in 8x8 blocks (5 x 3).
constexpr int kW = 40, kH = 24, kBlock = 8;
constexpr int kSeeds = 10;
// 32 samples a pixel; 8 under the sanitizers (each block's spread comes from its seeds, so the
// tolerance follows the count; the paths' lower variance holds at 8 too).
const int kSpp = std::max(8, test::sample_count(32));

struct Counts {
  uint64_t samples = 0, camera_rays = 0;
};

std::vector<double> render_blocks(const char* sampling, const char* filter, int seed, Counts* counts = nullptr,
                                  const AdaptiveOptions* adaptive = nullptr) {
  const std::string scene = fmt::format(R"(LookAt 0 0 -4  0 0 0  0 1 0
Camera "navarro" "float fov" 40 "float pupildiameter" 6 "string dispersionsampling" "{}"
Film "rgb" "integer xresolution" {} "integer yresolution" {} "string filename" "out.exr"
PixelFilter "{}"
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 3
)",
                                        sampling, kW, kH, filter, kSpp, seed);
  set_warnings_enabled(false);
  RenderSetup s = build_render_setup(parse_scene_string(scene + test::lit_sphere_world(5), "paths.pbrt", "/"), {});
  RenderOptions o;
  o.threads = 2;
  o.progress = false;
  o.adaptive = adaptive;
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, counters);
  if (counts) *counts = {counters.samples.load(), counters.camera_rays.load()};
  std::vector<double> blocks(size_t(kW / kBlock) * (kH / kBlock) * 3, 0.0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const RGB c = s.film->pixel_value(IVec2(x, y));
      const size_t b = (size_t(y / kBlock) * (kW / kBlock) + size_t(x / kBlock)) * 3;
      for (int ch = 0; ch < 3; ++ch) blocks[b + ch] += double(c[ch]) / (kBlock * kBlock);
    }
  return blocks;
}

struct Spread {
  std::vector<double> mean, se;  // over the seeds, per block and channel
};

// The mean and standard error over kSeeds renders of render(seed), seeds first_seed onwards.
template <typename Render>
Spread over_seeds(Render render, int first_seed) {
  std::vector<std::vector<double>> runs;
  for (int seed = 0; seed < kSeeds; ++seed) runs.push_back(render(first_seed + seed));
  Spread s;
  s.mean.assign(runs[0].size(), 0.0);
  s.se.assign(runs[0].size(), 0.0);
  for (const auto& r : runs)
    for (size_t i = 0; i < r.size(); ++i) s.mean[i] += r[i] / kSeeds;
  for (const auto& r : runs)
    for (size_t i = 0; i < r.size(); ++i) s.se[i] += (r[i] - s.mean[i]) * (r[i] - s.mean[i]) / (kSeeds - 1);
  for (double& v : s.se) v = std::sqrt(v / kSeeds);
  return s;
}

Spread over_seeds(const char* sampling, const char* filter) {
  return over_seeds([&](int seed) { return render_blocks(sampling, filter, seed); }, 1000);
}

void expect_agree(const Spread& a, const Spread& b) {
  int lit = 0;
  for (size_t i = 0; i < a.mean.size(); ++i) {
    const double se = std::hypot(a.se[i], b.se[i]);
    if (a.mean[i] > 0.01) ++lit;
    EXPECT_LE(std::abs(a.mean[i] - b.mean[i]), 4.5 * se + 1e-7)
        << "block " << i / 3 << " channel " << i % 3 << ": " << a.mean[i] << " against " << b.mean[i];
  }
  EXPECT_GT(lit, int(a.mean.size()) / 2);  // the comparison is of a lit image, not of black
}

// With a box filter MIS's splats are normalised by the wavelengths' shares (render/film.h): a
// ratio estimator, whose agreement with the paths also checks that its bias is below the noise.
TEST(WavelengthPaths, AgreeWithSpectralMisWithABoxFilter) {
  expect_agree(over_seeds("paths", "box"), over_seeds("mis", "box"));
}

TEST(WavelengthPaths, AgreeWithSpectralMisWithAGaussianFilter) {
  expect_agree(over_seeds("paths", "gaussian"), over_seeds("mis", "gaussian"));
}

// Through dispersive glass every path keeps only its hero wavelength, whose sample may have
// drawn its film point uniformly in its pixel (smooth splats, core/splatting_camera.h): the hero
// alone must still be splatted with the filter's weights, or the pixel reads the box filter's
// estimate. A checkerboard of one-pixel squares behind a slab of BK7 seen through the dispersive
// eye with the Gaussian filter: counted in its own pixel the hero gave the squares eight times
// the contrast the paths give (0.18 against 0.022). Pixel by pixel, the mean over the pixels of
// (MIS - paths)^2 / (se_MIS^2 + se_paths^2) is about 1.3 when they agree (Welch's t with about 9
// degrees of freedom; its standard error over 256 pixels about 0.15): 1.29 here, 22 with that bug.
constexpr int kGlassSide = 16;

std::vector<double> render_through_glass(const char* sampling, int seed) {
  const std::string scene = fmt::format(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "navarro" "float fov" 3.4 "float pupildiameter" 1 "string dispersionsampling" "{}"
Film "rgb" "integer xresolution" {} "integer yresolution" {} "string filename" "out.exr"
PixelFilter "gaussian"
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 5
WorldBegin
LightSource "distant" "point3 from" [0 3 3] "point3 to" [0 0 5] "rgb L" [3 3 3]
Material "dielectric" "spectrum eta" "glass-BK7"
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-2 -2 0.5  2 -2 0.5  2 2 0.5  -2 2 0.5]
Shape "trianglemesh" "integer indices" [0 2 1 0 3 2] "point3 P" [-2 -2 0.51  2 -2 0.51  2 2 0.51  -2 2 0.51]
Texture "checks" "spectrum" "checkerboard" "float uscale" 192 "float vscale" 192
  "rgb tex1" [0.9 0.9 0.9] "rgb tex2" [0.05 0.05 0.05]
Material "diffuse" "texture reflectance" "checks"
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point2 uv" [0 0 1 0 1 1 0 1]
  "point3 P" [-2 -2 5  2 -2 5  2 2 5  -2 2 5]
)",
                                        sampling, kGlassSide, kGlassSide, std::max(16, test::sample_count(64)), seed);
  set_warnings_enabled(false);
  const Image image = test::render_text(scene, "glass.pbrt");
  std::vector<double> green;
  for (int y = 0; y < kGlassSide; ++y)
    for (int x = 0; x < kGlassSide; ++x) green.push_back(image.at(x, y, 1));
  return green;
}

TEST(WavelengthPaths, AgreeWithSpectralMisPixelByPixelThroughDispersiveGlass) {
  const Spread mis = over_seeds([](int seed) { return render_through_glass("mis", seed); }, 2000);
  const Spread paths = over_seeds([](int seed) { return render_through_glass("paths", seed); }, 3000);
  double chi = 0.0, contrast_mis = 0.0, contrast_paths = 0.0, mean = 0.0;
  const size_t n = mis.mean.size();
  for (size_t i = 0; i < n; ++i) {
    const double d = mis.mean[i] - paths.mean[i];
    chi += d * d / (mis.se[i] * mis.se[i] + paths.se[i] * paths.se[i] + 1e-30) / double(n);
    mean += paths.mean[i] / double(n);
  }
  for (size_t i = 0; i < n; ++i) {
    contrast_mis += (mis.mean[i] - mean) * (mis.mean[i] - mean) / double(n);
    contrast_paths += (paths.mean[i] - mean) * (paths.mean[i] - mean) / double(n);
  }
  std::printf("[ stats ] through glass: mean normalised square difference %.2f; contrast %.4f (MIS), %.4f (paths)\n",
              chi, std::sqrt(contrast_mis), std::sqrt(contrast_paths));
  EXPECT_LT(chi, 2.0);
  EXPECT_GT(std::sqrt(contrast_paths), 0.05 * mean);  // the squares are resolved: a test of the filter
}

// "auto" is MIS (the same image, bit for bit), except paths with a box filter under adaptive
// sampling, which cannot splat.
TEST(WavelengthPaths, AutoPicksMisExceptPathsForABoxUnderAdaptiveSampling) {
  EXPECT_EQ(render_blocks("auto", "box", 7), render_blocks("mis", "box", 7));
  EXPECT_NE(render_blocks("auto", "box", 7), render_blocks("paths", "box", 7));
  EXPECT_EQ(render_blocks("auto", "gaussian", 7), render_blocks("mis", "gaussian", 7));
  EXPECT_NE(render_blocks("auto", "gaussian", 7), render_blocks("paths", "gaussian", 7));
  AdaptiveOptions adaptive;
  adaptive.target_error = 0.05;
  adaptive.min_spp = 8;
  adaptive.max_spp = kSpp;
  EXPECT_EQ(render_blocks("auto", "box", 7, nullptr, &adaptive), render_blocks("paths", "box", 7, nullptr, &adaptive));
  EXPECT_NE(render_blocks("auto", "box", 7, nullptr, &adaptive), render_blocks("mis", "box", 7, nullptr, &adaptive));
  EXPECT_EQ(render_blocks("auto", "gaussian", 7, nullptr, &adaptive),
            render_blocks("mis", "gaussian", 7, nullptr, &adaptive));
}

// --stats counts every camera ray: four a sample with paths, one with MIS.
TEST(WavelengthPaths, CountFourCameraRaysASample) {
  Counts paths, mis;
  render_blocks("paths", "box", 7, &paths);
  render_blocks("mis", "box", 7, &mis);
  EXPECT_EQ(paths.samples, uint64_t(kW) * kH * uint64_t(kSpp));
  EXPECT_EQ(paths.camera_rays, 4 * paths.samples);
  EXPECT_EQ(mis.camera_rays, mis.samples);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
