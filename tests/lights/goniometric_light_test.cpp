// The goniometric light: its intensity towards each pixel's direction is I times the pixel's
// channel average (pbrt-v4's equal-area map with y and z exchanged, placed by the CTM), its
// luminous power integrated numerically over the sphere equals "power" (times "scale"), and bad
// images are errors naming the file and the parameter.
#include "lights/goniometric_light.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "light_image_test_util.h"
#include "light_test_util.h"
#include "lights/sphere_mapping.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Pixel (x, y) of the 16 x 16 test diagram: channels that differ, a ramp and a bright square.
RGB diagram_pixel(int x, int y) {
  const float base = 0.1f + 0.05f * float(x) + (x >= 4 && x < 7 && y >= 9 && y < 12 ? 3.f : 0.f);
  return RGB(base, 2.f * base, 0.5f * float(y) / 15.f);
}

std::string diagram_file() {
  static const std::string path = [] {
    const std::string p = scratch_path("diagram.exr");
    write_rgb(p, 16, 16, diagram_pixel);
    return p;
  }();
  return path;
}

std::unique_ptr<Light> make_light(std::vector<Param> ps, const Transform& t = {}) {
  ParameterList params = make_params(std::move(ps));
  return create_goniometric_light(LightContext{params, t, ""});
}

const GoniometricLight& as_gonio(const std::unique_ptr<Light>& l) { return dynamic_cast<const GoniometricLight&>(*l); }

// The pixel's direction in the light's frame: the equal-area map's (x, y, z) is the light's (x, z, y).
Vec3 pixel_direction(int x, int y, int n) {
  const Vec3 d = equal_area_square_to_sphere(Vec2((float(x) + 0.5f) / float(n), (float(y) + 0.5f) / float(n)));
  return Vec3(d.x, d.z, d.y);
}

TEST(GoniometricLight, IntensityIsIPixelsChannelAverageTowardsItsDirection) {
  const Transform world_from_light = translate(Vec3(1, -2, 0.5)) * rotate(40, glm::normalize(Vec3(1, 2, 0.5)));
  auto light = make_light({string_param("filename", diagram_file()), rgb_param("I", 2, 2, 2)}, world_from_light);
  const auto& g = as_gonio(light);
  EXPECT_NEAR(glm::length(g.position() - Vec3(1, -2, 0.5)), 0.f, 1e-6f);
  const SampledWavelengths lambda = test::wavelengths();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const RGB c = diagram_pixel(x, y);
      const float expected = (c.r + c.g + c.b) / 3.f;
      const Vec3 w = world_from_light.vector(pixel_direction(x, y, 16));
      EXPECT_NEAR(g.diagram_value(w), expected, 1e-6f) << x << " " << y;
      // Received at distance 2 along w: 2 * value / 4, as a white emission.
      const Vec3 p = g.position() + 2.f * glm::normalize(w);
      auto s = light->sample_li(LightSampleContext{p, Vec3(0)}, Vec2(0.5f), lambda);
      ASSERT_TRUE(s);
      EXPECT_TRUE(test::same(s->L, test::emission(expected * 0.5f, lambda), 1e-4f)) << x << " " << y;
      EXPECT_NEAR(glm::length(s->wi + glm::normalize(w)), 0.f, 1e-5f);
    }
}

// pbrt-v4's orientation: the image centre along the light's +y, the corners along -y, the middle
// of the bottom edge along +z, of the right edge along +x.
TEST(GoniometricLight, ImageCentreLooksAlongTheLightsPlusY) {
  const std::string path = scratch_path("quadrants.exr");
  write_rgb(path, 8, 8, [](int x, int y) {
    const bool centre = x >= 3 && x < 5 && y >= 3 && y < 5, corner = (x == 0 || x == 7) && (y == 0 || y == 7);
    if (centre) return RGB(1.f);
    if (corner) return RGB(2.f);
    if (y == 7 && (x == 3 || x == 4)) return RGB(3.f);
    if (x == 7 && (y == 3 || y == 4)) return RGB(4.f);
    return RGB(0.f);
  });
  auto light = make_light({string_param("filename", path)});
  const auto& g = as_gonio(light);
  EXPECT_FLOAT_EQ(g.diagram_value(Vec3(0, 1, 0)), 1.f);
  EXPECT_FLOAT_EQ(g.diagram_value(Vec3(0, -1, 0)), 2.f);
  EXPECT_FLOAT_EQ(g.diagram_value(Vec3(0, 0, 1)), 3.f);
  EXPECT_FLOAT_EQ(g.diagram_value(Vec3(1, 0, 0)), 4.f);
  EXPECT_FLOAT_EQ(g.diagram_value(Vec3(-1, 0, 0)), 0.f);
}

// The luminous power, integral of luminance(I(w)) over the sphere by the midpoint rule in
// (theta, phi) (a quadrature that knows nothing of the equal-area map), is "power" times "scale".
// As in pbrt-v4, an RGB I's colour is not counted: with "rgb I" [3 3 3] the power is three times
// as much.
double integrated_luminous_power(const GoniometricLight& g) {
  const Vec3 probe(0, 1, 0);
  const double lum_I =
      test::luminance_of([&](const SampledWavelengths& l) { return g.intensity(probe, l); }) / g.diagram_value(probe);
  const int nt = 1000, np = 2000;
  double integral = 0;
  for (int i = 0; i < nt; ++i) {
    const double theta = (i + 0.5) * kPi / nt;
    double row = 0;
    for (int j = 0; j < np; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / np;
      row += g.diagram_value(
          Vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))));
    }
    integral += row * std::sin(theta) * (kPi / nt) * (2 * kPi / np);
  }
  // The diagram's mean over the sphere is its pixel mean (equal-area pixels).
  EXPECT_NEAR(integral / (4 * kPi), g.diagram_mean(), 2e-3 * g.diagram_mean());
  return lum_I * integral;
}

TEST(GoniometricLight, PowerNormalisationMatchesTheIntegratedIntensity) {
  auto white =
      make_light({string_param("filename", diagram_file()), float_param("power", 100), float_param("scale", 1.5)});
  EXPECT_NEAR(integrated_luminous_power(as_gonio(white)), 150.0, 150.0 * 2e-3);
  // The light sampler's weight is pbrt-v4's Phi, 4 pi I times the diagram's mean: for white I
  // its channel mean is the luminous power.
  EXPECT_NEAR(white->power(), 150.0, 150.0 * 1e-3);
  auto rgb = make_light({string_param("filename", diagram_file()), float_param("power", 100), float_param("scale", 1.5),
                         rgb_param("I", 3, 3, 3)});
  EXPECT_NEAR(integrated_luminous_power(as_gonio(rgb)), 450.0, 450.0 * 2e-3);
  // Without "power", I times the image: 4 pi 1.5 times the mean channel average.
  auto plain = make_light({string_param("filename", diagram_file()), float_param("scale", 1.5)});
  double mean = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) mean += (diagram_pixel(x, y).r + diagram_pixel(x, y).g + diagram_pixel(x, y).b) / 3.0;
  mean /= 256;
  EXPECT_NEAR(integrated_luminous_power(as_gonio(plain)), 4 * kPi * 1.5 * mean, 4 * kPi * 1.5 * mean * 2e-3);
}

void expect_error(std::vector<Param> ps, const std::vector<std::string>& mentions) {
  try {
    make_light(std::move(ps));
    ADD_FAILURE() << "accepted; expected an error mentioning " << mentions[0];
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test.pbrt:3:"), std::string::npos) << what;
    for (const std::string& m : mentions) EXPECT_NE(what.find(m), std::string::npos) << m << " in " << what;
  }
}

// Light paths (bdpt, sppm): sample_le's rays leave the light's position and carry its power
// (the diagram integrated over the sphere, checked above), within 5 standard errors; pdf_le
// gives each ray's density.
TEST(GoniometricLight, SampleLeRaysCarryThePower) {
  const Transform world_from_light = translate(Vec3(1, -2, 0.5)) * rotate(40, glm::normalize(Vec3(1, 2, 0.5)));
  auto light = make_light({string_param("filename", diagram_file()), float_param("power", 100)}, world_from_light);
  const LeEstimate e = sample_le_power(*light, 40000, 7, true, [&](const LightLeSample& s) {
    EXPECT_NEAR(glm::distance(s.ray.o, Vec3(1, -2, 0.5)), 0.f, 1e-5f);
    EXPECT_GT(as_gonio(light).diagram_value(s.ray.d), 0.f);
  });
  EXPECT_NEAR(e.power, light->power(), 5 * e.std_error);
  EXPECT_LT(e.std_error, 0.02 * light->power());
}

TEST(GoniometricLight, BadFilesAreErrorsNamingTheFileAndTheParameter) {
  expect_error({}, {"filename"});
  const std::string missing = scratch_path("no-such-diagram.exr");
  expect_error({string_param("filename", missing)}, {"filename", missing});
  const std::string wide = scratch_path("wide.exr");
  write_rgb(wide, 16, 8, [](int, int) { return RGB(1.f); });
  expect_error({string_param("filename", wide)}, {"filename", "16x8"});
  const std::string nan = scratch_path("nan.exr");
  write_rgb(nan, 8, 8, [](int x, int y) { return x == 3 && y == 5 ? RGB(std::nanf("")) : RGB(1.f); });
  expect_error({string_param("filename", nan)}, {"filename", "non-finite"});
  const std::string corrupt = scratch_path("corrupt.exr");
  {
    std::ofstream out(corrupt, std::ios::binary);
    out << "v/1\x01 not an OpenEXR file";
  }
  expect_error({string_param("filename", corrupt)}, {"filename", corrupt});
  expect_error({string_param("filename", diagram_file()), float_param("power", -1)}, {"power"});
  expect_error({string_param("filename", diagram_file()), point_param("from", 0, 1, 0)}, {"from"});
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
