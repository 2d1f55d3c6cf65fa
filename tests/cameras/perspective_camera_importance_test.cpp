// The perspective camera's importance (We, pdf_we, sample_wi), checked against what defines it:
// the measurement equation's normalisation (importance integrates to 1 over lens area times
// projected solid angle), the geometry of a disc seen from a point, and generate_ray.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/unity_id.h"
#include "cameras/perspective_camera.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr float kTwoPi = 6.28318530718f;

PerspectiveCamera make_camera(float lens_radius, const Transform& world_from_camera = Transform()) {
  PerspectiveCamera::Settings s;
  s.fov_deg = 50.f;
  s.lens_radius = lens_radius;
  s.focal_distance = 4.f;
  return PerspectiveCamera(world_from_camera, IVec2(40, 30), s);
}

// A direction uniform over the hemisphere z > 0 (density 1 / (2 pi)), written here rather than
// taken from core/sampling.h.
Vec3 hemisphere(float u, float v) {
  const float z = u, r = std::sqrt(std::max(0.f, 1.f - z * z));
  return Vec3(r * std::cos(kTwoPi * v), r * std::sin(kTwoPi * v), z);
}

// Mean and standard error of n draws of f().
template <typename F>
std::pair<double, double> monte_carlo(int n, F&& f) {
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = f();
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

// Pinhole: the integral of We cos over the sphere of directions is 1 (pbrt-v4 takes the
// pinhole's lens area as 1). Uniform hemisphere directions, 5 standard errors.
TEST(PerspectiveCameraImportance, PinholeImportanceIntegratesToOne) {
  const PerspectiveCamera cam = make_camera(0.f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  auto [mean, se] = monte_carlo(400000, [&] {
    const Vec3 d = hemisphere(u01(rng), u01(rng));
    return double(cam.we(Ray{Vec3(0.f), d})) * d.z * kTwoPi;
  });
  EXPECT_NEAR(mean, 1.0, 5 * se) << "standard error " << se;
  EXPECT_LT(se, 0.01);
  // Behind the camera: none.
  EXPECT_EQ(cam.we(Ray{Vec3(0.f), Vec3(0, 0, -1)}), 0.f);
}

// Thin lens: the integral over the lens disc and the hemisphere of We cos is 1, and the
// integral of pdf_we's direction density over solid angle is 1.
TEST(PerspectiveCameraImportance, ThinLensImportanceIntegratesToOneOverLensAndDirections) {
  const float r = 0.3f;
  const PerspectiveCamera cam = make_camera(r);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  const float lens_area = float(kPi) * r * r;
  auto [mean, se] = monte_carlo(400000, [&] {
    // A point uniform on the disc by rejection from its square (independent of the camera's
    // concentric mapping).
    Vec2 p;
    do p = Vec2(2.f * u01(rng) - 1.f, 2.f * u01(rng) - 1.f) * r;
    while (glm::dot(p, p) > r * r);
    const Vec3 d = hemisphere(u01(rng), u01(rng));
    return double(cam.we(Ray{Vec3(p, 0.f), d})) * d.z * kTwoPi * lens_area;
  });
  EXPECT_NEAR(mean, 1.0, 5 * se) << "standard error " << se;
  auto [pmean, pse] = monte_carlo(400000, [&] {
    const Vec3 d = hemisphere(u01(rng), u01(rng));
    float pos = 0.f, dir = 0.f;
    cam.pdf_we(Ray{Vec3(0.f), d}, &pos, &dir);
    EXPECT_FLOAT_EQ(dir > 0.f ? pos : 1.f / lens_area, 1.f / lens_area);
    return double(dir) * kTwoPi;
  });
  EXPECT_NEAR(pmean, 1.0, 5 * pse) << "standard error " << pse;
}

// sample_wi's lens points are uniform over the lens: the mean of 1 / pdf is the solid angle
// of the lens disc seen from an on-axis point at distance h, 2 pi (1 - h / sqrt(h^2 + r^2));
// and its density is pdf_we's area density turned into solid angle at the point.
TEST(PerspectiveCameraImportance, SampleWiDensityIsTheLensSolidAngleAndAgreesWithPdfWe) {
  const float r = 0.5f, h = 2.f;
  const PerspectiveCamera cam = make_camera(r);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  const Vec3 p_ref(0.f, 0.f, h);
  auto [mean, se] = monte_carlo(200000, [&] {
    const std::optional<CameraWiSample> cs = cam.sample_wi(p_ref, 0.f, Vec2(u01(rng), u01(rng)));
    EXPECT_TRUE(cs);
    if (!cs) return 0.0;
    float pos = 0.f, dir = 0.f;
    cam.pdf_we(Ray{cs->p_lens, -cs->wi}, &pos, &dir);
    const Vec3 to = p_ref - cs->p_lens;
    const float dist2 = glm::dot(to, to);
    EXPECT_NEAR(cs->pdf, pos * dist2 / std::abs(glm::dot(cs->n_lens, cs->wi)), 1e-4f * cs->pdf);
    return 1.0 / cs->pdf;
  });
  const double solid_angle = kTwoPi * (1.0 - h / std::sqrt(double(h) * h + double(r) * r));
  EXPECT_NEAR(mean, solid_angle, 5 * se + 1e-6) << "standard error " << se;
  // A point behind the camera sees no film.
  EXPECT_FALSE(cam.sample_wi(Vec3(0.f, 0.f, -1.f), 0.f, Vec2(0.5f)));
}

// A film point's ray, followed to a scene point, comes back through sample_wi to the same lens
// point and film point, with We = 1 / (A lens_area cos^4) (A: the film's area at distance 1).
TEST(PerspectiveCameraImportance, FilmPointsRoundTripThroughSampleWi) {
  const Transform placed = look_at(Vec3(1, 2, -5), Vec3(0.f), Vec3(0, 1, 0)).inverse();
  for (float r : {0.f, 0.2f}) {
    const PerspectiveCamera cam = make_camera(r, placed);
    const float tan_half = std::tan(radians(25.f)), aspect = 40.f / 30.f;
    const float film_area = (2.f * tan_half * aspect) * (2.f * tan_half);
    const float lens_area = r > 0.f ? float(kPi) * r * r : 1.f;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u01(0.f, 1.f);
    for (int i = 0; i < 200; ++i) {
      CameraSample s;
      s.p_film = Vec2(u01(rng) * 40.f, u01(rng) * 30.f);
      s.p_lens = Vec2(u01(rng), u01(rng));
      const std::optional<CameraRay> ray = cam.generate_ray(s);
      ASSERT_TRUE(ray);
      const Vec3 p_ref = ray->ray.at(1.f + 9.f * u01(rng));
      const std::optional<CameraWiSample> cs = cam.sample_wi(p_ref, 0.f, s.p_lens);
      ASSERT_TRUE(cs);
      EXPECT_NEAR(glm::distance(cs->p_lens, ray->ray.o), 0.f, 1e-4f);
      EXPECT_NEAR(cs->p_raster.x, s.p_film.x, 2e-3f);
      EXPECT_NEAR(cs->p_raster.y, s.p_film.y, 2e-3f);
      EXPECT_NEAR(glm::dot(cs->wi, ray->ray.d), -1.f, 1e-5f);
      // cos theta from the film point's pinhole direction (camera space, z = 1).
      const float x = (2.f * s.p_film.x / 40.f - 1.f) * aspect * tan_half;
      const float y = (1.f - 2.f * s.p_film.y / 30.f) * tan_half;
      const float cos_pinhole = 1.f / std::sqrt(1.f + x * x + y * y);
      if (r == 0.f) {
        const float expected = 1.f / (film_area * lens_area * std::pow(cos_pinhole, 4.f));
        EXPECT_NEAR(cs->Wi, expected, 1e-4f * expected);
      }
      const float cos_theta = glm::dot(ray->ray.d, cs->n_lens);
      const float expected = 1.f / (film_area * lens_area * std::pow(cos_theta, 4.f));
      EXPECT_NEAR(cam.we(ray->ray), expected, 1e-4f * expected);
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
