// The projection light: towards the direction through each pixel's centre on the plane z = 1
// (the image upright, "fov" across its shorter side) the intensity is the pixel's RGB times
// "scale"; nothing outside the image or behind the light; the luminous power integrated
// numerically over the sphere equals "power" (times "scale"); bad images are errors naming the
// file and the parameter.
#include "lights/projection_light.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "light_image_test_util.h"
#include "light_test_util.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

RGB slide_pixel(int x, int y) {
  return RGB(0.1f + 0.1f * float(x), 0.2f + 0.3f * float(y), (x + y) % 3 == 0 ? 2.f : 0.5f);
}

std::string slide_file(int w, int h) {
  const std::string p = scratch_path("slide" + std::to_string(w) + "x" + std::to_string(h) + ".exr");
  write_rgb(p, w, h, slide_pixel);
  return p;
}

std::unique_ptr<Light> make_light(std::vector<Param> ps, const Transform& t = {}) {
  ParameterList params = make_params(std::move(ps));
  return create_projection_light(LightContext{params, t, ""});
}

const ProjectionLight& as_projection(const std::unique_ptr<Light>& l) {
  return dynamic_cast<const ProjectionLight&>(*l);
}

// The direction (light space) through pixel (x, y) + offset of a w x h image: the image spans
// tan(fov / 2) times the aspect on its longer side, the top row up (+y), the left column at -x.
Vec3 through_pixel(float x, float y, int w, int h, float fov_deg) {
  const float t = std::tan(fov_deg * kPi / 360.f);
  const float hx = w > h ? t * float(w) / float(h) : t, hy = w > h ? t : t * float(h) / float(w);
  return Vec3(hx * (2.f * x / float(w) - 1.f), hy * (1.f - 2.f * y / float(h)), 1.f);
}

TEST(ProjectionLight, IntensityThroughEachPixelIsItsRgbTimesScale) {
  for (auto [w, h] : {std::pair{6, 4}, std::pair{3, 5}}) {
    const Transform world_from_light = translate(Vec3(0.5, 1, -2)) * rotate(70, glm::normalize(Vec3(-1, 2, 1)));
    auto light =
        make_light({string_param("filename", slide_file(w, h)), float_param("fov", 50), float_param("scale", 2)},
                   world_from_light);
    const auto& p = as_projection(light);
    const SampledWavelengths lambda = test::wavelengths();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (Vec2 o : {Vec2(0.5f), Vec2(0.05f, 0.9f), Vec2(0.95f, 0.1f)}) {
          const Vec3 wl = through_pixel(float(x) + o.x, float(y) + o.y, w, h, 50.f);
          const RGB got = p.intensity_rgb(world_from_light.vector(wl));
          const RGB want = 2.f * slide_pixel(x, y);
          for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f) << w << "x" << h << " " << x << " " << y;
        }
    // Received 3 units away towards the centre pixel's direction: I / 9 as an RGB emission.
    const Vec3 wc = glm::normalize(world_from_light.vector(through_pixel(0.5f * w, 0.5f * h, w, h, 50.f)));
    auto s = light->sample_li(LightSampleContext{p.position() + 3.f * wc, Vec3(0)}, Vec2(0.5f), lambda);
    ASSERT_TRUE(s);
    EXPECT_TRUE(test::same(s->L, test::emission(p.intensity_rgb(wc) / 9.f, lambda), 1e-4f));
    // Just outside each edge, sideways and behind: nothing.
    for (Vec3 wl : {through_pixel(-0.02f, 0.5f * h, w, h, 50.f), through_pixel(w + 0.02f, 0.5f * h, w, h, 50.f),
                    through_pixel(0.5f * w, -0.02f, w, h, 50.f), through_pixel(0.5f * w, h + 0.02f, w, h, 50.f),
                    Vec3(1, 0, 0), Vec3(0, 0, -1)})
      EXPECT_EQ(p.intensity_rgb(world_from_light.vector(wl)), RGB(0.f)) << wl.x << " " << wl.y << " " << wl.z;
  }
}

// The luminous power: luminance of I integrated over the sphere, here over the plane z = 1 by
// the midpoint rule with 16 x 16 points per pixel (dOmega = cos^3 theta dA), equals "power" times
// "scale"; without "power" it is the image's luminance integrated so.
double integrated_luminous_power(const ProjectionLight& p, int w, int h, float fov) {
  const int sub = 16;
  const Vec3 corner = through_pixel(0, 0, w, h, fov);
  const double hx = -corner.x, hy = corner.y, da = (2 * hx / (w * sub)) * (2 * hy / (h * sub));
  double sum = 0;
  for (int j = 0; j < h * sub; ++j)
    for (int i = 0; i < w * sub; ++i) {
      const double x = -hx + (i + 0.5) * 2 * hx / (w * sub), y = -hy + (j + 0.5) * 2 * hy / (h * sub);
      const double cos_theta = 1 / std::sqrt(1 + x * x + y * y);
      sum += luminance(p.intensity_rgb(Vec3(float(x), float(y), 1.f))) * cos_theta * cos_theta * cos_theta * da;
    }
  return sum;
}

TEST(ProjectionLight, PowerNormalisationMatchesTheIntegratedIntensity) {
  const int w = 24, h = 16;
  const std::string file = slide_file(w, h);
  for (float fov : {30.f, 100.f}) {
    auto light = make_light(
        {string_param("filename", file), float_param("fov", fov), float_param("power", 40), float_param("scale", 0.5)});
    // pbrt-v4 normalises by the pixel-centre rule; the exact integral differs by the variation
    // of cos^3 across a pixel: 1e-3 at this resolution.
    EXPECT_NEAR(integrated_luminous_power(as_projection(light), w, h, fov), 20.0, 20.0 * 1e-3) << fov;
    // The light sampler's weight is pbrt-v4's Phi averaged over the channels.
    const RGB phi = as_projection(light).power_rgb();
    EXPECT_NEAR(luminance(phi), 20.f, 20.f * 1e-4f);
    EXPECT_FLOAT_EQ(light->power(), (phi.r + phi.g + phi.b) / 3.f);
  }
  auto plain = make_light({string_param("filename", file), float_param("fov", 60)});
  double sum = 0;
  const Vec3 corner = through_pixel(0, 0, w, h, 60.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec3 c = through_pixel(x + 0.5f, y + 0.5f, w, h, 60.f);
      sum += luminance(slide_pixel(x, y)) * std::pow(1.0 / glm::length(c), 3.0);
    }
  const double pixel_centre_rule = sum * 4 * corner.x * corner.y / (w * h);
  EXPECT_NEAR(integrated_luminous_power(as_projection(plain), w, h, 60.f), std::abs(pixel_centre_rule),
              1e-3 * std::abs(pixel_centre_rule));
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

// Light paths (bdpt, sppm): sample_le's rays leave the light's position inside the image's
// frustum and carry the power of a grey slide, its intensity integrated over the image as above
// (16 x 16 points per pixel), within 5 standard errors; pdf_le gives each ray's density.
TEST(ProjectionLight, SampleLeRaysCarryThePower) {
  const std::string grey = scratch_path("grey-slide.exr");
  write_rgb(grey, 6, 4, [](int x, int y) { return RGB(0.2f + 0.15f * float(x) + 0.4f * float(y % 2)); });
  const Transform world_from_light = translate(Vec3(0.5, 1, -2)) * rotate(70, glm::normalize(Vec3(-1, 2, 1)));
  auto light =
      make_light({string_param("filename", grey), float_param("fov", 50), float_param("scale", 2)}, world_from_light);
  const auto& p = as_projection(light);
  const LeEstimate e = sample_le_power(*light, 40000, 8, true, [&](const LightLeSample& s) {
    EXPECT_NEAR(glm::distance(s.ray.o, p.position()), 0.f, 1e-5f);
    EXPECT_GT(luminance(p.intensity_rgb(s.ray.d)), 0.f);
  });
  // The integral is the same for the light unturned, which integrated_luminous_power expects.
  auto unturned = make_light({string_param("filename", grey), float_param("fov", 50), float_param("scale", 2)});
  const double integral = integrated_luminous_power(as_projection(unturned), 6, 4, 50.f);
  EXPECT_NEAR(e.power, integral, 5 * e.std_error);
  EXPECT_LT(e.std_error, 0.02 * integral);
}

TEST(ProjectionLight, BadFilesAndParametersAreErrorsNamingThem) {
  expect_error({}, {"filename"});
  const std::string missing = scratch_path("no-such-slide.png");
  expect_error({string_param("filename", missing)}, {"filename", missing});
  const std::string inf = scratch_path("inf.exr");
  write_rgb(inf, 4, 4, [](int x, int) { return x == 2 ? RGB(INFINITY, 0.f, 0.f) : RGB(1.f); });
  expect_error({string_param("filename", inf)}, {"filename", "non-finite"});
  expect_error({string_param("filename", slide_file(6, 4)), float_param("fov", 180)}, {"fov"});
  expect_error({string_param("filename", slide_file(6, 4)), float_param("scale", -1)}, {"scale"});
  expect_error({string_param("filename", slide_file(6, 4)), rgb_param("I", 1, 1, 1)}, {"unused parameter \"rgb I\""});
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
