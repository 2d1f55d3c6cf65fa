// Normalised splats (render/film.h): a dispersive eye's spectral MIS with a box filter divides
// each pixel by the sums of its wavelengths' shares rather than by its sample count. Checked on
// a uniform sky through the 6 mm Navarro eye at 70 degrees, where the pupil vignettes the
// periphery: the image must agree with the wavelength paths (each wavelength its own ray, no
// shares), which is what the lost rays' shares make exact (giving a lost ray a share of 1 at
// every wavelength instead is 0.2 % off in red and blue), and it must be about as quiet as the
// paths (the plain mean, dividing by the sample count, was 4.5 times as noisy here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../support/sample_count.h"
#include "../support/unity_id.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr int kW = 48, kH = 32;
const int kSpp = std::max(16, test::sample_count(256));

std::vector<double> render_sky(const char* sampling, int seed, RenderCounters* counted = nullptr) {
  const std::string scene = fmt::format(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "navarro" "float fov" 70 "float pupildiameter" 6 "string dispersionsampling" "{}"
Film "rgb" "integer xresolution" {} "integer yresolution" {} "string filename" "sky.exr"
PixelFilter "box"
Sampler "zsobol" "integer pixelsamples" {} "integer seed" {}
Integrator "path" "integer maxdepth" 1
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
)",
                                        sampling, kW, kH, kSpp, seed);
  set_warnings_enabled(false);
  RenderSetup s = build_render_setup(parse_scene_string(scene, "sky.pbrt", "/"), {});
  RenderOptions o;
  o.threads = 2;
  o.progress = false;
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, counted ? *counted : counters);
  std::vector<double> rgb;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const RGB c = s.film->pixel_value(IVec2(x, y));
      rgb.insert(rgb.end(), {double(c.r), double(c.g), double(c.b)});
    }
  return rgb;
}

double channel_mean(const std::vector<double>& a, const std::vector<double>& b, int c) {
  double m = 0.0;
  for (size_t i = size_t(c); i < a.size(); i += 3) m += (a[i] + b[i]) / double(a.size() / 3 * 2);
  return m;
}

// The rms relative difference of two renders' pixels: the noise of one render, times sqrt 2.
double noise(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = 2.0 * (a[i] - b[i]) / std::max(a[i] + b[i], 1e-3);
    s += d * d / double(a.size());
  }
  return std::sqrt(s);
}

TEST(NormalisedSplats, AgreeWithWavelengthPathsOnAVignettedSkyAndAreAsQuiet) {
  const std::vector<double> mis1 = render_sky("mis", 1), mis2 = render_sky("mis", 2);
  const std::vector<double> paths1 = render_sky("paths", 1), paths2 = render_sky("paths", 2);
  // Measured at 256 samples a pixel: the two agree within 1.2e-4 per channel (the white lost
  // share is 1.7e-3 to 2.2e-3 off); the noise of the means grows as 1 / sqrt(samples).
  const double tolerance = 6e-4 * std::sqrt(256.0 / kSpp);
  for (int c = 0; c < 3; ++c) {
    const double mis = channel_mean(mis1, mis2, c), paths = channel_mean(paths1, paths2, c);
    EXPECT_GT(paths, 0.5);  // the sky is seen
    EXPECT_NEAR(mis / paths, 1.0, tolerance) << "channel " << c;
  }
  // Measured: 1.0 to 1.3 times the paths' noise per channel (the plain mean: 3.7 to 4.5 times).
  EXPECT_LT(noise(mis1, mis2), 1.6 * noise(paths1, paths2));
}

// render --stats reports the camera rays a lost sample traces for its shares apart from the
// camera rays (they start no scene path): three per lost sample, the other wavelengths' own.
TEST(NormalisedSplats, StatsCountTheLostSamplesRaysForShares) {
  RenderCounters mis, paths;
  render_sky("mis", 1, &mis);
  render_sky("paths", 1, &paths);
  EXPECT_GT(mis.camera_rays_lost.load(), 0u);  // the periphery is vignetted
  EXPECT_EQ(mis.camera_rays_for_shares.load(), 3 * mis.camera_rays_lost.load());
  EXPECT_EQ(mis.camera_rays.load(), mis.samples.load());
  EXPECT_GT(paths.camera_rays_lost.load(), 0u);
  EXPECT_EQ(paths.camera_rays_for_shares.load(), 0u);  // each wavelength traced its own ray already
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
