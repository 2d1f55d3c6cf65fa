// Infinite lights. Constant: the irradiance estimator built from sample_li gives pi L on a
// horizontal patch. Image maps (equal-area and lat-long, written here as EXR files): the
// sampled directions follow pixel luminance and pdf_li (chi-square, 1% significance),
// pdf_li integrates to 1 over the sphere, samples agree with pdf_li and Le, "illuminance"
// normalises the +z irradiance, the transform orients the map, and bad files are errors
// naming "filename". Statistical tolerances are 4 standard errors (two-sided ~6e-5).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <functional>

#include "../support/unity_id.h"
#include "core/error.h"
#include "core/sampling.h"
#include "core/srgb.h"
#include "core/transform.h"
#include "light_test_util.h"
#include "lights/infinite_light.h"
#include "lights/sphere_mapping.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

// A scratch folder for the images the tests write, removed when the program exits.
struct ScratchDir {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("eyetrace_lights_test_" + std::to_string(getpid()));
  ScratchDir() { std::filesystem::create_directories(dir); }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

std::string temp_path(const std::string& name) {
  static ScratchDir scratch;
  return (scratch.dir / name).string();
}

// Float pixels for .exr; for .png the values are the 8-bit file's codes / 255 (sRGB-encoded).
void write_image(const std::string& path, int w, int h, const std::function<RGB(int, int)>& pixel) {
  const bool png = path.size() > 4 && path.substr(path.size() - 4) == ".png";
  Image img;
  img.width = w;
  img.height = h;
  img.pixels.resize(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = png ? srgb_to_linear(pixel(x, y)[c]) : pixel(x, y)[c];
  eyetrace::write_image(path, img);
}

// A sky with a bright sun, a colour gradient and a black region (zero density must never
// be sampled), given as radiance per direction.
RGB sky(const Vec3& d) {
  Vec3 sun = glm::normalize(Vec3(0.4f, -0.3f, 0.8f));
  if (d.z < -0.7f) return RGB(0.f);
  float v = 0.3f + 6.f * std::exp(-6.f * (1.f - glm::dot(d, sun)));
  return v * RGB(1.f, 0.8f + 0.2f * d.x, 0.6f);
}

std::string write_equal_area_sky(int res) {
  std::string path = temp_path(fmt::format("sky_equal_area_{}.exr", res));
  write_image(path, res, res,
              [&](int x, int y) { return sky(equal_area_square_to_sphere(Vec2((x + 0.5f) / res, (y + 0.5f) / res))); });
  return path;
}

std::string write_latlong_sky(int h) {
  std::string path = temp_path(fmt::format("sky_latlong_{}.exr", h));
  write_image(path, 2 * h, h,
              [&](int x, int y) { return sky(latlong_square_to_sphere(Vec2((x + 0.5f) / (2 * h), (y + 0.5f) / h))); });
  return path;
}

std::unique_ptr<Light> make_infinite(std::vector<Param> ps, const Transform& t = Transform()) {
  ParameterList params = make_params(std::move(ps));
  return create_infinite_light(LightContext{params, t, ""});
}

// Irradiance on a patch with normal n from N sample_li samples: sum L cos / pdf.
Estimate irradiance_estimate(const Light& light, const Vec3& n, int count, uint32_t seed) {
  Uniform rng(seed);
  std::vector<double> x(count, 0.0);
  LightSampleContext ctx{Vec3(0.f), n};
  for (int i = 0; i < count; ++i) {
    SampledWavelengths lambda = SampledWavelengths::sample_visible(rng.next());
    auto s = light.sample_li(ctx, rng.next2(), lambda);
    if (s) x[i] = luminance_estimate(s->L, lambda) * std::max(0.f, glm::dot(n, s->wi)) / s->pdf;
  }
  return estimate(x);
}

TEST(UniformInfiniteLight, IrradianceOnHorizontalPatchIsPiL) {
  auto light = make_infinite({rgb_param("L", 0.5, 1, 2)});
  const int n = 200000;
  Estimate e = irradiance_estimate(*light, Vec3(0, 0, 1), n, 1);
  double expected = kPi * luminance(RGB(0.5f, 1.f, 2.f));
  EXPECT_NEAR(e.mean, expected, 4.0 * e.std_error) << "stderr " << e.std_error;
  EXPECT_LT(e.std_error, 0.01 * expected);  // the test has teeth
  // Every sample agrees with pdf_li and Le.
  Uniform rng(2);
  for (int i = 0; i < 100; ++i) {
    const SampledWavelengths lambda = test::wavelengths();
    auto s = light->sample_li(LightSampleContext{Vec3(1, 2, 3), Vec3(0, 0, 1)}, rng.next2(), lambda);
    ASSERT_TRUE(s);
    EXPECT_FLOAT_EQ(light->pdf_li(LightSampleContext{}, s->wi, nullptr), s->pdf);
    EXPECT_TRUE(test::same(light->Le(Ray{Vec3(0), s->wi}, lambda), s->L, 0.f));
  }
  EXPECT_TRUE(light->is_infinite());
  EXPECT_FALSE(light->is_delta());
}

TEST(UniformInfiniteLight, IlluminanceSetsIrradianceAndPowerCoversScene) {
  auto light = make_infinite({float_param("illuminance", 3)});
  const float L = test::luminance_of([&](const SampledWavelengths& l) { return light->Le(Ray{}, l); });
  EXPECT_NEAR(kPi * L, 3.f, 3e-3f);
  Estimate e = irradiance_estimate(*light, glm::normalize(Vec3(1, -2, 0.5f)), 100000, 3);
  EXPECT_NEAR(e.mean, 3.0, 4.0 * e.std_error);
  Bounds3 b;
  b.extend(Vec3(-1, -1, -1));
  b.extend(Vec3(1, 1, 1));
  light->preprocess(b);
  float r = std::sqrt(3.f);
  EXPECT_NEAR(light->power(), 4.f * kPi * kPi * r * r * L, 1e-3f * light->power());
  auto s = light->sample_li(LightSampleContext{Vec3(0.5f, 0, 0), Vec3(0)}, Vec2(0.3f, 0.6f), test::wavelengths());
  EXPECT_NEAR(glm::distance(s->p_light, Vec3(0.5f, 0, 0)), 2.f * r, 1e-4f);
}

// Which pixel of the map a direction falls in.
int pixel_of(const ImageInfiniteLight& light, const Vec3& w) {
  const RGBImage& img = light.map().image();
  Vec2 uv =
      light.map().mapping() == SphereMapping::EqualArea ? equal_area_sphere_to_square(w) : latlong_sphere_to_square(w);
  int x = std::clamp(int(uv.x * img.width), 0, img.width - 1);
  int y = std::clamp(int(uv.y * img.height), 0, img.height - 1);
  return y * img.width + x;
}

// Probability of each pixel, computed here from the image: luminance times solid angle.
std::vector<double> pixel_probabilities(const ImageInfiniteLight& light) {
  const RGBImage& img = light.map().image();
  std::vector<double> p(img.pixels.size());
  double sum = 0.0;
  for (int y = 0; y < img.height; ++y) {
    double omega = 1.0;
    if (light.map().mapping() == SphereMapping::LatLong)
      omega = std::cos(kPi * y / img.height) - std::cos(kPi * (y + 1) / img.height);
    for (int x = 0; x < img.width; ++x) {
      p[size_t(y) * img.width + x] = luminance(img.at(x, y)) * omega;
      sum += p[size_t(y) * img.width + x];
    }
  }
  for (double& v : p) v /= sum;
  return p;
}

void check_samples_follow_pixel_luminance(const ImageInfiniteLight& light) {
  const int n = 300000;
  std::vector<double> expected = pixel_probabilities(light), observed(expected.size(), 0.0);
  for (double& e : expected) e *= n;
  Uniform rng(17);
  for (int i = 0; i < n; ++i) {
    auto s = light.sample_li(LightSampleContext{}, rng.next2(), test::wavelengths());
    if (s) observed[pixel_of(light, s->wi)] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_EQ(r.impossible, 0);
  EXPECT_GT(r.p_value, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
}

// Directions binned in (z, phi), whose cells have equal solid angle; expected counts from
// pdf_li integrated over each cell by a 24 x 24 midpoint rule.
void check_samples_follow_pdf_li(const Light& light) {
  const int nz = 16, nphi = 32, sub = 24, n = 300000;
  std::vector<double> expected(nz * nphi, 0.0), observed(nz * nphi, 0.0);
  double dz = 2.0 / (nz * sub), dphi = 2.0 * kPi / (nphi * sub);
  for (int iz = 0; iz < nz * sub; ++iz)
    for (int ip = 0; ip < nphi * sub; ++ip) {
      double z = -1.0 + (iz + 0.5) * dz, phi = (ip + 0.5) * dphi;
      double r = std::sqrt(1.0 - z * z);
      Vec3 w(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
      expected[(iz / sub) * nphi + ip / sub] += n * light.pdf_li(LightSampleContext{}, w, nullptr) * dz * dphi;
    }
  Uniform rng(23);
  for (int i = 0; i < n; ++i) {
    auto s = light.sample_li(LightSampleContext{}, rng.next2(), test::wavelengths());
    if (!s) continue;
    int iz = std::clamp(int((s->wi.z + 1.f) * 0.5f * nz), 0, nz - 1);
    float phi = std::atan2(s->wi.y, s->wi.x);
    if (phi < 0.f) phi += 2.f * kPi;
    int ip = std::clamp(int(phi / (2.f * kPi) * nphi), 0, nphi - 1);
    observed[iz * nphi + ip] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_EQ(r.impossible, 0);
  EXPECT_GT(r.p_value, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
}

double pdf_integral(const Light& light) {
  const int nz = 600, nphi = 1200;
  double sum = 0.0;
  for (int iz = 0; iz < nz; ++iz)
    for (int ip = 0; ip < nphi; ++ip) {
      double z = -1.0 + (iz + 0.5) * 2.0 / nz, phi = (ip + 0.5) * 2.0 * kPi / nphi;
      double r = std::sqrt(1.0 - z * z);
      Vec3 w(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
      sum += light.pdf_li(LightSampleContext{}, w, nullptr);
    }
  return sum * (2.0 / nz) * (2.0 * kPi / nphi);
}

void check_samples_agree_with_pdf_li_and_le(const Light& light) {
  Uniform rng(29);
  for (int i = 0; i < 5000; ++i) {
    auto s =
        light.sample_li(LightSampleContext{Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 0, 1)}, rng.next2(), test::wavelengths());
    if (!s) continue;
    ASSERT_GT(s->pdf, 0.f);
    ASSERT_FLOAT_EQ(light.pdf_li(LightSampleContext{}, s->wi, nullptr), s->pdf);
    ASSERT_TRUE(test::same(light.Le(Ray{Vec3(0), s->wi}, test::wavelengths()), s->L, 0.f));
  }
}

class ImageInfiniteLightTest : public ::testing::TestWithParam<bool> {
 protected:
  std::unique_ptr<Light> make(std::vector<Param> extra = {}) {
    bool latlong = GetParam();
    extra.push_back(string_param("filename", latlong ? write_latlong_sky(32) : write_equal_area_sky(32)));
    return make_infinite(std::move(extra));
  }
};

// Light paths from an environment image: directions by the map's density (pdf_le agrees with
// each), and in total pi r^2 times the radiance integrated over the sphere, which uniformly
// sampled directions of Le estimate independently; within 5 combined standard errors.
TEST_P(ImageInfiniteLightTest, SampleLeRaysCarryWhatTheEnvironmentSends) {
  auto light = make();
  Bounds3 b;
  b.extend(Vec3(-1.f));
  b.extend(Vec3(1.f));
  light->preprocess(b);
  const double disc = kPi * sqr(b.radius());
  const LeEstimate e = sample_le_power(*light, 20000, 10, true, [](const LightLeSample&) {});
  const SampledWavelengths lambda = test::wavelengths();
  const float white = test::emission(1.f, lambda)[1];
  Uniform rng(11);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = light->Le(Ray{Vec3(0.f), sample_uniform_sphere(rng.next2())}, lambda)[1] / white * 4 * kPi;
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(e.power, disc * mean, 5 * std::sqrt(sqr(e.std_error) + sqr(disc * se)));
  EXPECT_LT(e.std_error, 0.02 * e.power);
}

TEST_P(ImageInfiniteLightTest, SamplesFollowPixelLuminanceChiSquare) {
  auto light = make();
  check_samples_follow_pixel_luminance(dynamic_cast<const ImageInfiniteLight&>(*light));
}

TEST_P(ImageInfiniteLightTest, SampledDirectionsFollowPdfLiChiSquare) { check_samples_follow_pdf_li(*make()); }

TEST_P(ImageInfiniteLightTest, PdfIntegratesToOneOverSphere) { EXPECT_NEAR(pdf_integral(*make()), 1.0, 3e-3); }

TEST_P(ImageInfiniteLightTest, SamplesAgreeWithPdfLiAndLe) { check_samples_agree_with_pdf_li_and_le(*make()); }

TEST_P(ImageInfiniteLightTest, IlluminanceNormalisesUpwardIrradiance) {
  auto light = make({float_param("illuminance", 2)});
  Estimate e = irradiance_estimate(*light, Vec3(0, 0, 1), 200000, 31);
  EXPECT_NEAR(e.mean, 2.0, 4.0 * e.std_error + 2e-3) << "stderr " << e.std_error;
  // Independently of sample_li: uniform directions and Le.
  Uniform rng(37);
  const int n = 400000;
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) {
    Vec3 w = sample_uniform_hemisphere(rng.next2());
    SampledWavelengths lambda = SampledWavelengths::sample_visible(rng.next());
    x[i] = luminance_estimate(light->Le(Ray{Vec3(0), w}, lambda), lambda) * w.z / uniform_hemisphere_pdf();
  }
  Estimate u = estimate(x);
  EXPECT_NEAR(u.mean, 2.0, 4.0 * u.std_error + 2e-3) << "stderr " << u.std_error;
}

INSTANTIATE_TEST_SUITE_P(Mappings, ImageInfiniteLightTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "LatLong" : "EqualArea"; });

TEST(ImageInfiniteLight, PowerIsFourPiSquaredR2TimesMeanRadiance) {
  std::string path = temp_path("grey_equal_area.exr");
  write_image(path, 8, 8, [](int, int) { return RGB(0.5f); });
  auto light = make_infinite({string_param("filename", path), float_param("scale", 3)});
  Bounds3 b;
  b.extend(Vec3(0));
  b.extend(Vec3(2, 0, 0));
  light->preprocess(b);
  EXPECT_NEAR(light->power(), 4.f * kPi * kPi * 1.f * 1.5f, 1e-3f);
}

// A map bright only around its +z pole, turned by the CTM as pbrt scenes do for +y up.
TEST(ImageInfiniteLight, TransformOrientsTheMap) {
  std::string path = temp_path("pole_equal_area.exr");
  const int res = 16;
  write_image(path, res, res, [&](int x, int y) {
    float z = equal_area_square_to_sphere(Vec2((x + 0.5f) / res, (y + 0.5f) / res)).z;
    return RGB(z > 0.9f ? 10.f : 0.01f);
  });
  auto light = make_infinite({string_param("filename", path)}, rotate(-90.f, Vec3(1, 0, 0)));
  const SampledWavelengths lambda = test::wavelengths();
  EXPECT_TRUE(test::same(light->Le(Ray{Vec3(0), Vec3(0, 1, 0)}, lambda), test::emission(10.f, lambda), 1e-5f));
  EXPECT_TRUE(test::same(light->Le(Ray{Vec3(0), Vec3(0, 0, 1)}, lambda), test::emission(0.01f, lambda), 1e-5f));
  Uniform rng(41);
  int near_y = 0;
  for (int i = 0; i < 1000; ++i) {
    auto s = light->sample_li(LightSampleContext{}, rng.next2(), test::wavelengths());
    if (s && s->wi.y > 0.85f) ++near_y;
  }
  // The bright cap holds 10 / (10 + 0.01 * 19) of the luminance (cap is 1/20 of the sphere).
  EXPECT_GT(near_y, 950);
}

TEST(ImageInfiniteLight, EightBitImagesAreDecodedFromSrgb) {
  std::string path = temp_path("grey.png");
  write_image(path, 4, 4, [](int, int) { return RGB(128.f / 255.f); });
  auto light = make_infinite({string_param("filename", path)});
  // IEC 61966-2-1: ((c + 0.055) / 1.055)^2.4 for c = 128/255.
  const SampledWavelengths lambda = test::wavelengths();
  EXPECT_TRUE(test::same(light->Le(Ray{}, lambda), test::emission(0.2158605f, lambda), 1e-5f));
}

std::string error_of(std::vector<Param> ps) {
  try {
    make_infinite(std::move(ps));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(ImageInfiniteLight, MissingFileIsAnErrorNamingFilenameAndPath) {
  std::string path = temp_path("no_such_sky.exr");
  std::string msg = error_of({string_param("filename", path)});
  EXPECT_NE(msg.find("\"filename\""), std::string::npos) << msg;
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("test.pbrt:3:7"), std::string::npos) << msg;
}

TEST(ImageInfiniteLight, RelativeFilenameIsResolvedAgainstSearchDir) {
  std::string path = write_equal_area_sky(8);
  ParameterList params = make_params({string_param("filename", fs::path(path).filename().string())});
  auto light = create_infinite_light(LightContext{params, Transform(), fs::path(path).parent_path().string()});
  EXPECT_TRUE(light->is_infinite());
}

TEST(ImageInfiniteLight, WrongAspectAndDoubleEmissionAreErrors) {
  std::string path = temp_path("wide.exr");
  write_image(path, 30, 20, [](int, int) { return RGB(1.f); });
  std::string msg = error_of({string_param("filename", path)});
  EXPECT_NE(msg.find("\"filename\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("30x20"), std::string::npos) << msg;
  std::string both = error_of({string_param("filename", write_equal_area_sky(8)), rgb_param("L", 1, 1, 1)});
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
}

// A square window of side 2a at height h above the origin, its normal (+z) pointing out.
Param square_portal(float a, float h) {
  return num_param("point3", "portal", {-a, -a, h, -a, a, h, a, a, h, a, -a, h});
}

// Through a portal the sky is a square emitter of the sky's radiance: the irradiance on an
// upward patch below its centre is pi L times the square's form factor (the same formula as
// the square area light's), and the power sampling weighs the light by is pi A L.
TEST(InfiniteLightPortal, UniformSkyThroughASquareWindowGivesTheFormFactorIrradiance) {
  const float a = 0.8f, h = 1.3f, L = 2.f;
  auto light = make_infinite({rgb_param("L", L, L, L), square_portal(a, h)});
  Estimate e = irradiance_estimate(*light, Vec3(0, 0, 1), 200000, 3);
  const double X = double(a) / h, root = std::sqrt(1.0 + X * X);
  const double expected = kPi * L * 4.0 / (2.0 * kPi) * 2.0 * X / root * std::atan(X / root);
  EXPECT_NEAR(e.mean, expected, 4.0 * e.std_error) << "stderr " << e.std_error;
  EXPECT_NEAR(light->power(), kPi * 4.0 * a * a * L, 1e-4);
}

// An image sky through a window: the light's estimate (half map sampling, half portal area
// sampling) against a deterministic quadrature over the window of L cos cos' / d^2.
TEST(InfiniteLightPortal, ImageSkyThroughAWindowMatchesAQuadratureOverTheWindow) {
  const float a = 0.6f, h = 0.9f;
  auto light = make_infinite({string_param("filename", write_equal_area_sky(32)), square_portal(a, h)});
  const int n = 120;
  double quadrature = 0.0;
  const double cell = double(2 * a) / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 q(-a + float((i + 0.5) * cell), -a + float((j + 0.5) * cell), h);
      const double d2 = glm::dot(q, q), cos = h / std::sqrt(d2);
      const Vec3 w = glm::normalize(q);
      const float Lum = test::luminance_of(
          [&](const SampledWavelengths& l) {
            return light->Le(Ray{Vec3(0.f), w}, l);
          },
          16);
      quadrature += Lum * cos * cos / d2 * cell * cell;
    }
  Estimate e = irradiance_estimate(*light, Vec3(0, 0, 1), 200000, 5);
  EXPECT_NEAR(e.mean, quadrature, 4.0 * e.std_error + 2e-3 * quadrature) << "stderr " << e.std_error;
}

TEST(InfiniteLightPortal, SamplesAgreeWithPdfLiAndLeAndTheSkyIsSeenOnlyThroughThePortal) {
  for (bool image : {false, true}) {
    auto light = make_infinite({image ? string_param("filename", write_equal_area_sky(16)) : rgb_param("L", 1, 2, 3),
                                square_portal(0.5f, 1.f)});
    const LightSampleContext ctx{Vec3(0.f), Vec3(0, 0, 1)};
    Uniform rng(31);
    int through = 0;
    for (int i = 0; i < 5000; ++i) {
      auto s = light->sample_li(ctx, rng.next2(), test::wavelengths());
      if (!s) continue;
      ++through;
      ASSERT_GT(s->pdf, 0.f);
      ASSERT_FLOAT_EQ(light->pdf_li(ctx, s->wi, nullptr), s->pdf);
      ASSERT_TRUE(test::same(light->Le(Ray{Vec3(0), s->wi}, test::wavelengths()), s->L, 0.f));
      ASSERT_LT(std::max(std::abs(s->wi.x), std::abs(s->wi.y)) / s->wi.z, 0.5f + 1e-5f);  // through the window
    }
    EXPECT_GT(through, 2000) << image;
    const auto lambda = test::wavelengths();
    EXPECT_FALSE(is_black(light->Le(Ray{Vec3(0.f), Vec3(0, 0, 1)}, lambda))) << image;
    EXPECT_TRUE(is_black(light->Le(Ray{Vec3(0.f), glm::normalize(Vec3(1, 0, 1))}, lambda))) << image;  // past its edge
    EXPECT_TRUE(is_black(light->Le(Ray{Vec3(0.f, 0.f, 2.f), Vec3(0, 0, 1)}, lambda))) << image;        // from outside
    EXPECT_EQ(light->pdf_li(ctx, glm::normalize(Vec3(1, 0, 1)), nullptr), 0.f) << image;
  }
}

TEST(InfiniteLightPortal, APortalThatIsNotARectangleIsAnErrorNamingIt) {
  for (const std::vector<double>& corners :
       {std::vector<double>{0, 0, 1, 1, 0, 1, 1, 1, 1}, std::vector<double>{0, 0, 1, 0, 1, 1, 1, 1.5, 1, 1, 0, 1}}) {
    std::string e;
    try {
      make_infinite({rgb_param("L", 1, 1, 1), num_param("point3", "portal", corners)});
    } catch (const SceneError& err) {
      e = err.what();
    }
    EXPECT_NE(e.find("\"portal\""), std::string::npos) << e;
    EXPECT_NE(e.find("test.pbrt:3:7"), std::string::npos) << e;
  }
}

// Light paths from a uniform environment: directions over the whole sphere (their mean about
// 0), points on the disc that bounds the scene, rays started outside it; the total they carry
// is 4 pi^2 r^2 L (the light's power), every sample exactly. A portal's light is refused.
TEST(InfiniteLight, SampleLeRaysFromTheUniformEnvironmentCarryThePower) {
  auto light = make_infinite({rgb_param("L", 0.5, 0.5, 0.5)});
  Bounds3 b;
  b.extend(Vec3(-1, 0, 0));
  b.extend(Vec3(1, 2, 4));
  light->preprocess(b);
  const float r = b.radius();
  Vec3 mean_dir(0.f);
  const LeEstimate e = sample_le_power(*light, 4000, 8, true, [&](const LightLeSample& s) {
    EXPECT_GE(glm::distance(s.ray.o, b.center()), r * (1 - 1e-5f));
    mean_dir += s.ray.d / 4000.f;
  });
  EXPECT_EQ(e.samples, 4000);
  EXPECT_NEAR(e.power, 4 * kPi * kPi * r * r * 0.5, 1e-3 * e.power);
  EXPECT_NEAR(e.power, light->power(), 1e-3 * e.power);
  EXPECT_LT(glm::length(mean_dir), 5 * std::sqrt(1.0 / 3 / 4000) * std::sqrt(3.0));
  auto portal = make_infinite({num_param("point3", "portal", {-1, 1, 0, 1, 1, 0, 1, 1, 1, -1, 1, 1})});
  EXPECT_FALSE(portal->emits_rays());
  EXPECT_FALSE(portal->sample_le(Vec2(0.5f), Vec2(0.5f), test::wavelengths(), 0.f));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
