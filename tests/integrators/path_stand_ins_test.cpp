// pbrt-v4's "sppm", rendered by the path tracer: the camera inside a closed, two-sided emitting
// diffuse sphere (radiance Le, albedo a) sees exactly Le (1 + a + ... + a^d) after d bounces,
// whatever the estimator, so "maxdepth" is checked against that sum; its own parameters are
// checked as pbrt-v4 checks them. (bdpt: tests/integrators/bdpt_integrator_test.cpp.)
#include <gtest/gtest.h>

#include "../support/render_text.h"

namespace eyetrace {
namespace {

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

std::string error_of(const std::string& integrator) {
  try {
    test::render_text(emitting_sphere(integrator), "standin.pbrt");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// 16384 estimates, each between 0 and the sum of the series (< 2): the standard error of the
// mean is below 2 / sqrt(16384) / 2 = 0.008 at worst; 0.03 is about four of them.
TEST(PathStandIns, SppmHonoursMaxdepthAndAcceptsItsParameters) {
  const std::string sppm = "\"sppm\" \"integer maxdepth\" 3 \"float radius\" 0.02 \"integer photonsperiteration\" 1000";
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere(sppm))), 1.875, 0.03);
}

TEST(PathStandIns, BadParametersAreNamed) {
  std::string e = error_of("\"sppm\" \"float radius\" -1");
  EXPECT_NE(e.find("standin.pbrt:6:"), std::string::npos) << e;
  EXPECT_NE(e.find("radius"), std::string::npos) << e;
}

}  // namespace
}  // namespace eyetrace
