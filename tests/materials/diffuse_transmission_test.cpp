// The "diffusetransmission" material (pbrt-v4's): through the renderer a plane lit from in front
// shines with its reflectance and lit from behind with its transmittance (both R/pi E cos, an
// analytic answer); "scale" multiplies both; a closed lossless sphere (R + T = 1) in a uniform
// environment returns the environment's radiance (a white furnace: conservation of energy).
// The BxDF's own sampling and energy are in bsdf_properties_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/render_text.h"
#include "../support/unity_id.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct Mean {
  double value = 0, std_error = 0;
};

Mean render_mean(const std::string& text) {
  const Image img = test::render_text(text, "dt.pbrt");
  double sum = 0, sum2 = 0;
  for (float v : img.pixels) {
    sum += v;
    sum2 += double(v) * v;
  }
  const double n = double(img.pixels.size());
  return {sum / n, std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)) / n)};
}

// A square at z = 0 seen from +z, a distant light from (x, 0, z), the material given.
double lit_plane(float light_z, const std::string& material) {
  return render_mean(fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 8
    Film "rgb" "integer xresolution" 8 "integer yresolution" 8
    Sampler "independent" "integer pixelsamples" 4
    Integrator "path" "integer maxdepth" 1
    WorldBegin
    LightSource "distant" "point3 from" [-1 0 {}] "point3 to" [0 0 0] "rgb L" [1 1 1]
    Material {}
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
  )",
                                 light_z, material))
      .value;
}

TEST(DiffuseTransmission, ReflectsInFrontAndTransmitsBehind) {
  const double reference = lit_plane(1.f, R"("diffuse" "rgb reflectance" [0.5 0.5 0.5])");
  ASSERT_GT(reference, 0.0);
  const std::string m = R"("diffusetransmission" "rgb reflectance" [0.3 0.3 0.3] "rgb transmittance" [0.6 0.6 0.6])";
  EXPECT_NEAR(lit_plane(1.f, m) / reference, 0.3 / 0.5, 1e-4);
  EXPECT_NEAR(lit_plane(-1.f, m) / reference, 0.6 / 0.5, 1e-4);
  // "scale" multiplies both; the defaults are 0.25 each.
  EXPECT_NEAR(lit_plane(-1.f, m + R"( "float scale" 0.5)") / reference, 0.3 / 0.5, 1e-4);
  EXPECT_NEAR(lit_plane(1.f, R"("diffusetransmission")") / reference, 0.25 / 0.5, 1e-4);
  EXPECT_NEAR(lit_plane(-1.f, R"("diffusetransmission")") / reference, 0.25 / 0.5, 1e-4);
}

TEST(DiffuseTransmission, LosslessSphereInAFurnaceReturnsTheEnvironment) {
  const Mean m = render_mean(R"(
    LookAt 0 0 -3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16
    Sampler "halton" "integer pixelsamples" 256
    Integrator "path" "integer maxdepth" 100
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "rgb L" [1 1 1]
    Material "diffusetransmission" "rgb reflectance" [0.4 0.4 0.4] "rgb transmittance" [0.6 0.6 0.6]
    Shape "sphere" "float radius" 1
  )");
  // Paths longer than maxdepth are cut (a bias of well under 1e-3 at these albedos).
  EXPECT_NEAR(m.value, 1.0, std::max(0.003, 4 * m.std_error));
  EXPECT_LT(m.std_error, 0.002);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
