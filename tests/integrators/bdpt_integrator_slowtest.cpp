// bdpt's t = 1 strategies on a caustic (tests/data/pbrt-v4/bdpt-caustic.pbrt at 32 x 32: a point
// light beside a glass sphere over a diffuse floor, seen by a pinhole), against independent
// estimates, on the floor pixels alone (those where the camera sees the floor directly):
// - with the point light replaced by a sphere light of radius 0.2 and the same power, bdpt's
//   floor carries what the path tracer finds (its BSDF-sampled rays hit the light through the
//   glass), within 4 combined standard errors;
// - a sphere light shrunk to radius 0.02 gives the point light's floor (the light's extent moves
//   light by a first-order amount in its radius: +2.8 % at 0.2 in the sppm test, so at 0.02
//   within 0.5 % besides the noise);
// - without t = 1 bdpt misses the point light's caustic, as the path tracer does: its floor is
//   more than 5 % darker (the caustic is about a tenth of the floor's light).
#include <gtest/gtest.h>

#include "../support/masked_renders.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::masked;
using test::masked_pair;
using test::MeanAndError;
using test::replaced;
using test::with_line;

std::string read_scene(const std::string& name) { return test::read_pbrt_v4_scene(name); }

Image render(const std::string& text, int spp, uint64_t seed = 1) { return test::render_32(text, spp, seed); }

TEST(BdptIntegrator, CausticSeenDirectlyCarriesThePowerPathFindsThroughASphereLight) {
  const std::string caustic = read_scene("bdpt-caustic.pbrt");
  auto sphere = [](const std::string& text, double r) { return test::caustic_with_sphere_light(text, r); };
  const std::string path = with_line(caustic, "Integrator", "Integrator \"path\" \"integer maxdepth\" 5");
  const std::vector<bool> mask = test::caustic_floor_pixels(caustic);

  const MeanAndError path_sphere =
      masked_pair(render(sphere(path, 0.2), 4096, 1), render(sphere(path, 0.2), 4096, 2), mask);
  const MeanAndError bdpt_sphere =
      masked_pair(render(sphere(caustic, 0.2), 256, 1), render(sphere(caustic, 0.2), 256, 2), mask);
  const MeanAndError bdpt_point = masked_pair(render(caustic, 256, 3), render(caustic, 256, 4), mask);
  const MeanAndError bdpt_small =
      masked_pair(render(sphere(caustic, 0.02), 256, 5), render(sphere(caustic, 0.02), 256, 6), mask);
  const std::string without =
      with_line(caustic, "Integrator", "Integrator \"bdpt\" \"integer maxdepth\" 5 \"bool lighttracing\" false");
  const double without_t1 = masked(render(without, 64, 7), mask);
  std::printf(
      "floor means: path sphere 0.2 %.5f +- %.5f, bdpt sphere 0.2 %.5f +- %.5f, bdpt point %.5f +- %.5f, bdpt "
      "sphere 0.02 %.5f +- %.5f, bdpt point without t = 1 %.5f\n",
      path_sphere.mean, path_sphere.std_error, bdpt_sphere.mean, bdpt_sphere.std_error, bdpt_point.mean,
      bdpt_point.std_error, bdpt_small.mean, bdpt_small.std_error, without_t1);
  EXPECT_NEAR(bdpt_sphere.mean, path_sphere.mean, 4 * std::hypot(bdpt_sphere.std_error, path_sphere.std_error));
  EXPECT_NEAR(bdpt_small.mean, bdpt_point.mean,
              4 * std::hypot(bdpt_small.std_error, bdpt_point.std_error) + 0.005 * bdpt_point.mean);
  EXPECT_LT(without_t1, 0.95 * bdpt_point.mean);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
