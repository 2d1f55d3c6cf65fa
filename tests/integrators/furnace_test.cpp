// Analytic scenes for the integrators: a convex diffuse object inside a uniform environment
// of radiance Le reflects exactly rho * Le (every reflected ray escapes to the environment),
// so rho = 1 is the white furnace: the object must vanish into the background.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Mean radiance over the image of a sphere that fills the whole view.
double mean_furnace_radiance(float rho, float Le, const std::string& integrator, int spp, int threads = 0) {
  std::string text = fmt::format(R"(
    LookAt 0 0 -3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "independent" "integer pixelsamples" {}
    Integrator "{}" "integer maxdepth" 50
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "rgb L" [{} {} {}]
    Material "diffuse" "rgb reflectance" [{} {} {}]
    Shape "sphere" "float radius" 1
  )",
                                 spp, integrator, Le, Le, Le, rho, rho, rho);
  SceneDescription desc = parse_scene_string(text, "furnace.pbrt", ".");
  RenderSetup s = build_render_setup(desc, {});
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = threads;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  EXPECT_EQ(counters.camera_rays_lost.load(), 0u);
  Image img = s.film->image();
  double sum = 0;
  for (float v : img.pixels) sum += v;
  return sum / img.pixels.size();
}

// 16x16 pixels x 64 samples = 16384 independent estimates with a standard deviation below
// Le (each is Le times a product of albedos and MIS weights <= 1), so the standard error of
// the mean is below 0.008 Le; the tolerance 0.04 Le is five standard errors.
TEST(PathIntegrator, WhiteFurnaceMatchesEnvironment) {
  EXPECT_NEAR(mean_furnace_radiance(1.f, 1.f, "path", 64), 1.0, 0.04);
}

TEST(PathIntegrator, ConvexDiffuseObjectReflectsAlbedoTimesEnvironment) {
  EXPECT_NEAR(mean_furnace_radiance(0.5f, 2.f, "path", 64), 1.0, 0.04);
}

TEST(DirectIntegrator, ConvexDiffuseObjectReflectsAlbedoTimesEnvironment) {
  // One bounce is exact here: nothing reflected by a convex object comes back to it.
  EXPECT_NEAR(mean_furnace_radiance(0.8f, 1.f, "direct", 64), 0.8, 0.04);
}

// Energy never grows: with albedo below one every pixel stays below the environment (plus
// noise, bounded by 5 standard errors of a pixel's 256-sample mean).
TEST(PathIntegrator, EnergyNeverGrows) { EXPECT_LT(mean_furnace_radiance(0.9f, 1.f, "path", 64), 0.9 + 0.04); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
