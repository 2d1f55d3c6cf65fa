// pbrt-v4's "bdpt", rendered by the path tracer: the camera inside a closed, two-sided
// emitting diffuse sphere (radiance Le, albedo a) sees exactly Le (1 + a + ... + a^d) after d
// bounces, whatever the estimator, so its "maxdepth" is checked against that sum; its own
// parameters are checked as pbrt-v4 checks them. ("sppm" is tested in sppm_integrator_test.cpp.)
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
TEST(PathStandIns, BdptHonoursMaxdepth) {
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere("\"bdpt\" \"integer maxdepth\" 1"))), 1.5, 0.03);
  EXPECT_NEAR(test::image_mean(test::render_text(emitting_sphere("\"bdpt\""))), 1.96875, 0.03);  // default 5
}

TEST(PathStandIns, BadParametersAreNamed) {
  std::string e = error_of("\"bdpt\" \"float rrthreshold\" 0.5");  // pbrt-v4's bdpt has no such parameter
  EXPECT_NE(e.find("rrthreshold"), std::string::npos) << e;
  e = error_of("\"bdpt\" \"integer maxdepth\" -1");
  EXPECT_NE(e.find("maxdepth"), std::string::npos) << e;
}

}  // namespace
}  // namespace eyetrace
