// Diffuse area lights over hand-written analytic shapes (a disk and a square, uniform area
// sampling), independent of the shape plugins. The sample_li irradiance estimator matches
// closed forms: E = pi L sin^2(alpha) under a disk on its axis, and the Lambert form factor
// of a square; one-sided lights are dark from behind; pdf_li equals each sample's density
// and integrates to 1 over the solid angle the emitter covers; "power" fixes pi L A.
// Statistical tolerances are 4 standard errors (two-sided ~6e-5).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "../support/unity_id.h"
#include "core/error.h"
#include "core/sampling.h"
#include "light_test_util.h"
#include "lights/diffuse_area_light.h"
#include "render/image_io.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Base for the fake shapes: only what area lights use is real.
class FakeShape : public Shape {
 public:
  unsigned attach(RTCDevice, RTCScene) const override { return RTC_INVALID_GEOMETRY_ID; }
  SurfaceInteraction interaction(const Ray&, float, unsigned, Vec2, Vec3) const override { return {}; }
};

// A disk of radius R centred at c with unit normal n.
class FakeDisk : public FakeShape {
 public:
  FakeDisk(Vec3 c, Vec3 n, float R) : c_(c), frame_(glm::normalize(n)), R_(R) {}
  float area() const override { return kPi * R_ * R_; }
  ShapeSample sample_area(Vec2 u) const override {
    Vec2 d = sample_uniform_disk_concentric(u) * R_;
    return ShapeSample{c_ + frame_.to_world(Vec3(d, 0.f)), frame_.n, u, 1.f / area()};
  }
  Bounds3 bounds() const override {
    Bounds3 b;
    b.extend(c_ - Vec3(R_));
    b.extend(c_ + Vec3(R_));
    return b;
  }
  // Where the ray from o along unit w meets the disk, if it does.
  std::optional<Vec3> hit(const Vec3& o, const Vec3& w) const {
    float denom = glm::dot(w, frame_.n);
    if (denom == 0.f) return std::nullopt;
    float t = glm::dot(c_ - o, frame_.n) / denom;
    if (t <= 0.f) return std::nullopt;
    Vec3 p = o + t * w;
    if (glm::distance(p, c_) > R_) return std::nullopt;
    return p;
  }
  const Vec3& normal() const { return frame_.n; }

 private:
  Vec3 c_;
  Frame frame_;
  float R_;
};

// The square [-a, a]^2 in the plane z = h, normal -z (facing the origin).
class FakeSquare : public FakeShape {
 public:
  FakeSquare(float a, float h) : a_(a), h_(h) {}
  float area() const override { return 4.f * a_ * a_; }
  ShapeSample sample_area(Vec2 u) const override {
    return ShapeSample{Vec3((2.f * u.x - 1.f) * a_, (2.f * u.y - 1.f) * a_, h_), Vec3(0, 0, -1), u, 1.f / area()};
  }
  Bounds3 bounds() const override {
    Bounds3 b;
    b.extend(Vec3(-a_, -a_, h_));
    b.extend(Vec3(a_, a_, h_));
    return b;
  }

 private:
  float a_, h_;
};

std::unique_ptr<Light> make_area(const Shape& shape, std::vector<Param> ps) {
  static TextureStore textures;
  ParameterList params = make_params(std::move(ps));
  return create_diffuse_area_light(AreaLightContext{params, shape, false, textures, ""});
}

Estimate irradiance_estimate(const Light& light, const LightSampleContext& ctx, int count, uint32_t seed) {
  Uniform rng(seed);
  std::vector<double> x(count, 0.0);
  for (int i = 0; i < count; ++i) {
    SampledWavelengths lambda = SampledWavelengths::sample_visible(rng.next());
    auto s = light.sample_li(ctx, rng.next2(), lambda);
    if (s) x[i] = luminance_estimate(s->L, lambda) * std::max(0.f, glm::dot(ctx.n, s->wi)) / s->pdf;
  }
  return estimate(x);
}

TEST(DiffuseAreaLight, DiskOnAxisIrradianceIsPiLSinSquaredAlpha) {
  const float R = 1.5f, h = 2.f, L = 3.f;
  FakeDisk disk(Vec3(0, 0, h), Vec3(0, 0, -1), R);
  auto light = make_area(disk, {rgb_param("L", L, L, L)});
  Estimate e = irradiance_estimate(*light, LightSampleContext{Vec3(0), Vec3(0, 0, 1)}, 200000, 1);
  double sin2 = double(R) * R / (double(R) * R + double(h) * h);
  double expected = kPi * L * sin2;
  EXPECT_NEAR(e.mean, expected, 4.0 * e.std_error) << "stderr " << e.std_error;
  EXPECT_LT(e.std_error, 0.01 * expected);
}

// Lambert's form factor from a point to a centred parallel square of side 2a at height h:
// 4 corner rectangles a x a, each (1 / 2 pi)(2 X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2))).
TEST(DiffuseAreaLight, SquareOnAxisIrradianceMatchesFormFactor) {
  const float a = 0.8f, h = 1.3f, L = 2.f;
  FakeSquare square(a, h);
  auto light = make_area(square, {rgb_param("L", L, L, L)});
  Estimate e = irradiance_estimate(*light, LightSampleContext{Vec3(0), Vec3(0, 0, 1)}, 200000, 2);
  double X = double(a) / h, s = std::sqrt(1.0 + X * X);
  double form_factor = 4.0 * (1.0 / (2.0 * kPi)) * 2.0 * X / s * std::atan(X / s);
  double expected = kPi * L * form_factor;
  EXPECT_NEAR(e.mean, expected, 4.0 * e.std_error) << "stderr " << e.std_error;
}

TEST(DiffuseAreaLight, OneSidedIsDarkFromBehindTwoSidedIsNot) {
  FakeDisk away(Vec3(0, 0, 2), Vec3(0, 0, 1), 1.f);  // normal points away from the origin
  auto one = make_area(away, {});
  LightSampleContext ctx{Vec3(0), Vec3(0, 0, 1)};
  Uniform rng(3);
  const SampledWavelengths lambda = test::wavelengths();
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(one->sample_li(ctx, rng.next2(), lambda).has_value());
  auto two = make_area(away, {bool_param("twosided", true)});
  Estimate e = irradiance_estimate(*two, ctx, 100000, 4);
  double expected = kPi * 1.0 * (1.0 / (1.0 + 4.0));
  EXPECT_NEAR(e.mean, expected, 4.0 * e.std_error);

  SurfaceInteraction hit;
  hit.n = Vec3(0, 0, 1);
  EXPECT_TRUE(test::same(one->L(hit, Vec3(0, 0, 1), lambda), test::emission(1.f, lambda)));
  EXPECT_TRUE(one->L(hit, Vec3(0.3f, 0, -1), lambda).is_black());
  EXPECT_TRUE(test::same(two->L(hit, Vec3(0.3f, 0, -1), lambda), test::emission(1.f, lambda)));
}

TEST(DiffuseAreaLight, PdfLiEqualsSampleDensity) {
  FakeDisk disk(Vec3(0.5f, -1, 3), glm::normalize(Vec3(0.3f, 0.2f, -1)), 1.2f);
  auto light = make_area(disk, {});
  LightSampleContext ctx{Vec3(0.2f, 0.1f, 0.f), glm::normalize(Vec3(0.1f, 0, 1))};
  Uniform rng(5);
  const SampledWavelengths lambda = test::wavelengths();
  for (int i = 0; i < 1000; ++i) {
    auto s = light->sample_li(ctx, rng.next2(), lambda);
    ASSERT_TRUE(s.has_value());
    SurfaceInteraction hit;
    hit.p = s->p_light;
    hit.n = s->n_light;
    EXPECT_NEAR(light->pdf_li(ctx, s->wi, &hit), s->pdf, 1e-4f * s->pdf);
    EXPECT_TRUE(test::same(light->L(hit, -s->wi, lambda), s->L, 0.f));
  }
  EXPECT_EQ(light->pdf_li(ctx, Vec3(0, 0, 1), nullptr), 0.f);
}

// pdf_li is a density over the directions that reach the light: its integral over the
// hemisphere, by uniform hemisphere sampling with an analytic ray-disk test, is 1.
TEST(DiffuseAreaLight, PdfLiIntegratesToOneOverTheEmitter) {
  FakeDisk disk(Vec3(0.5f, -1, 3), glm::normalize(Vec3(0.3f, 0.2f, -1)), 1.2f);
  auto light = make_area(disk, {});
  LightSampleContext ctx{Vec3(0.f), Vec3(0, 0, 1)};
  Uniform rng(6);
  const int n = 400000;
  std::vector<double> x(n, 0.0);
  for (int i = 0; i < n; ++i) {
    Vec3 w = sample_uniform_hemisphere(rng.next2());
    std::optional<Vec3> p = disk.hit(ctx.p, w);
    if (!p) continue;
    SurfaceInteraction hit;
    hit.p = *p;
    hit.n = disk.normal();
    x[i] = light->pdf_li(ctx, w, &hit) / uniform_hemisphere_pdf();
  }
  Estimate e = estimate(x);
  EXPECT_NEAR(e.mean, 1.0, 4.0 * e.std_error) << "stderr " << e.std_error;
}

TEST(DiffuseAreaLight, PowerIsPiLAAndPowerParameterSetsIt) {
  FakeSquare square(0.5f, 1.f);  // area 1
  auto light = make_area(square, {rgb_param("L", 2, 2, 2), float_param("scale", 1.5)});
  EXPECT_NEAR(light->power(), kPi * 3.f, 1e-5f);
  auto two = make_area(square, {rgb_param("L", 2, 2, 2), bool_param("twosided", true)});
  EXPECT_NEAR(two->power(), 2.f * kPi * 2.f, 1e-5f);
  auto target = make_area(square, {float_param("power", 10)});
  EXPECT_NEAR(target->power(), 10.f, 1e-4f);
  SurfaceInteraction hit;
  hit.n = Vec3(0, 0, -1);
  const float y = test::luminance_of([&](const SampledWavelengths& l) { return target->L(hit, Vec3(0, 0, -1), l); });
  EXPECT_NEAR(y, 10.f / kPi, 2e-3f * 10.f / kPi);  // L = Phi / (pi A), luminance
}

// A scratch folder for the images the tests write, removed when the program exits.
struct ScratchDir {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("eyetrace_area_test_" + std::to_string(getpid()));
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

// pbrt-v4 looks the image up at (u, 1 - v): uv (0.25, 0.75) is the centre of the top-left pixel.
TEST(DiffuseAreaLight, ImageEmissionIsLookedUpAtUOneMinusV) {
  std::string path = temp_path("emit.exr");
  Image img;
  img.width = img.height = 2;
  img.pixels = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};  // red green / blue white
  write_image(path, img);
  FakeSquare square(0.5f, 1.f);
  auto light = make_area(square, {string_param("filename", path), float_param("scale", 2)});
  SurfaceInteraction hit;
  hit.n = Vec3(0, 0, -1);
  hit.uv = Vec2(0.25f, 0.75f);
  const SampledWavelengths lambda = test::wavelengths();
  EXPECT_TRUE(test::same(light->L(hit, Vec3(0, 0, -1), lambda), test::emission(RGB(2, 0, 0), lambda), 1e-5f));
  hit.uv = Vec2(0.75f, 0.25f);
  EXPECT_TRUE(test::same(light->L(hit, Vec3(0, 0, -1), lambda), test::emission(RGB(2, 2, 2), lambda), 1e-5f));
  hit.uv = Vec2(0.5f, 0.5f);  // the average of all four
  EXPECT_TRUE(test::same(light->L(hit, Vec3(0, 0, -1), lambda), test::emission(RGB(1, 1, 1), lambda), 1e-4f));
}

TEST(DiffuseAreaLight, BadParametersAreErrors) {
  FakeSquare square(0.5f, 1.f);
  try {
    make_area(square, {string_param("filename", "/nonexistent/emit.exr")});
    FAIL();
  } catch (const SceneError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("\"filename\""), std::string::npos) << msg;
    EXPECT_NE(msg.find("/nonexistent/emit.exr"), std::string::npos) << msg;
  }
  EXPECT_THROW(make_area(square, {rgb_param("L", -1, 1, 1)}), SceneError);
  EXPECT_THROW(make_area(square, {float_param("power", 0)}), SceneError);
}

// Light paths: sample_le's rays leave the emitting side (either side when two-sided) with a
// cosine-weighted direction, so each carries exactly pi A L (2 pi A L two-sided), the light's
// power; pdf_le gives each ray's densities.
TEST(DiffuseAreaLight, SampleLeRaysCarryThePower) {
  FakeDisk disk(Vec3(0, 0, 2), Vec3(0, 0, -1), 0.5f);
  for (bool two_sided : {false, true}) {
    auto light = make_area(disk, {rgb_param("L", 3, 3, 3), bool_param("twosided", two_sided)});
    int back = 0;
    const LeEstimate e = sample_le_power(*light, 4000, 9, true, [&](const LightLeSample& s) {
      EXPECT_EQ(s.n, Vec3(0, 0, -1));
      EXPECT_NEAR(s.pdf_pos, 1.f / disk.area(), 1e-6f);
      if (glm::dot(s.ray.d, s.n) < 0.f) ++back;
    });
    EXPECT_EQ(e.samples, 4000);
    const double power = (two_sided ? 2 : 1) * kPi * disk.area() * 3;
    EXPECT_NEAR(e.power, power, 1e-3 * power) << two_sided;
    EXPECT_NEAR(e.power, light->power(), 1e-3 * power) << two_sided;
    if (two_sided)
      EXPECT_NEAR(back, 2000, 5 * std::sqrt(1000.0));  // half of them from the back
    else
      EXPECT_EQ(back, 0);
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
