// The spherical camera against the closed forms of its two mappings (pbrt-v4's conventions: the
// sphere's y and z exchanged, so the camera's up is the equal-area centre and the
// equirectangular top row), their inverses at random points, the equal-area property, the
// continuation across the equal-area square's edges, the shutter, and the parameters.
#include "cameras/spherical_camera.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"
#include "lights/sphere_mapping.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kPiD = std::numbers::pi;

Param string_param(const std::string& name, const std::string& value) {
  Param p;
  p.type = "string";
  p.name = name;
  p.strings = {value};
  p.loc = SourceLoc{"scene.pbrt", 5, 18};
  return p;
}

Param float_param(const std::string& name, std::vector<double> v) {
  Param p;
  p.type = "float";
  p.name = name;
  p.numbers = std::move(v);
  p.loc = SourceLoc{"scene.pbrt", 5, 18};
  return p;
}

std::unique_ptr<Camera> make_camera(std::vector<Param> params, IVec2 res, const Transform& world_from_camera = {}) {
  ParameterList list(SourceLoc{"scene.pbrt", 5, 1});
  for (Param& p : params) list.add(std::move(p));
  return create_spherical_camera(CameraContext{list, world_from_camera, res, "."});
}

Vec3 ray_direction(const Camera& cam, Vec2 p_film) {
  CameraSample cs;
  cs.p_film = p_film;
  auto r = cam.generate_ray(cs);
  EXPECT_TRUE(r);
  EXPECT_EQ(r->ray.o, Vec3(0.f));
  return r->ray.d;
}

// theta = pi v from the camera's +y, phi = 2 pi u from +x towards +z.
TEST(SphericalCamera, EquirectangularDirectionsMatchTheClosedForm) {
  const IVec2 res(64, 32);
  auto cam = make_camera({string_param("mapping", "equirectangular")}, res);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int i = 0; i < 300; ++i) {
    const double u = u01(rng), v = u01(rng);
    const Vec3 d = ray_direction(*cam, Vec2(float(u * res.x), float(v * res.y)));
    const double theta = kPiD * v, phi = 2 * kPiD * u;
    EXPECT_NEAR(d.x, std::sin(theta) * std::cos(phi), 2e-5);
    EXPECT_NEAR(d.y, std::cos(theta), 2e-5);
    EXPECT_NEAR(d.z, std::sin(theta) * std::sin(phi), 2e-5);
    // The inverse: back to the pixel position.
    const Vec2 back = latlong_sphere_to_square(Vec3(d.x, d.z, d.y));
    EXPECT_NEAR(back.y, v, 2e-5);
    if (std::sin(theta) > 1e-2) EXPECT_NEAR(std::remainder(back.x - u, 1.0), 0.0, 2e-5);
  }
  // The top row looks up, the middle of the middle row (u = 1/2) along -x, u = 1/4 forward.
  EXPECT_GT(ray_direction(*cam, Vec2(10.f, 0.01f)).y, 0.9999f);
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(32.f, 16.f)) - Vec3(-1, 0, 0)), 0.f, 1e-5f);
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(16.f, 16.f)) - Vec3(0, 0, 1)), 0.f, 1e-5f);
}

// Clarberg's equal-area octahedral map as pbrt-v4 writes it (EqualAreaSquareToSphere), written
// out here, with y and z exchanged.
Vec3 equal_area_closed_form(double u, double v) {
  const double up = 2 * u - 1, vp = 2 * v - 1;
  const double signed_distance = 1 - (std::abs(up) + std::abs(vp));
  const double r = 1 - std::abs(signed_distance);
  const double phi = (r == 0 ? 1 : (std::abs(vp) - std::abs(up)) / r + 1) * kPiD / 4;
  const double z = std::copysign(1 - r * r, signed_distance);
  const double s = r * std::sqrt(2 - r * r);
  const double x = std::copysign(std::cos(phi), up) * s, y = std::copysign(std::sin(phi), vp) * s;
  return Vec3(float(x), float(z), float(y));
}

TEST(SphericalCamera, EqualAreaDirectionsMatchTheClosedFormAndInvert) {
  const IVec2 res(48, 48);
  auto cam = make_camera({}, res);  // equalarea is the default
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int i = 0; i < 300; ++i) {
    const double u = u01(rng), v = u01(rng);
    const Vec3 d = ray_direction(*cam, Vec2(float(u * res.x), float(v * res.y)));
    EXPECT_NEAR(glm::length(d - equal_area_closed_form(u, v)), 0.f, 3e-5f) << u << " " << v;
    const Vec2 back = equal_area_sphere_to_square(Vec3(d.x, d.z, d.y));
    EXPECT_NEAR(back.x, u, 5e-5);
    EXPECT_NEAR(back.y, v, 5e-5);
  }
  // The centre looks up, the middle of the right edge along +x, of the bottom edge forward (+z),
  // the corners down.
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(24.f, 24.f)) - Vec3(0, 1, 0)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(48.f, 24.f)) - Vec3(1, 0, 0)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(24.f, 48.f)) - Vec3(0, 0, 1)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(ray_direction(*cam, Vec2(0.f, 0.f)) - Vec3(0, -1, 0)), 0.f, 1e-6f);
}

// Equal area: pixels uniform over the image give directions uniform over the sphere, so the cap
// y > 1/2 (a quarter of the sphere's area) gets a quarter of them (binomial, 4.4 sigma: 1e-5).
TEST(SphericalCamera, EqualAreaPixelsCoverEqualSolidAngles) {
  auto cam = make_camera({}, IVec2(16, 16));
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  const int n = 200000;
  int cap = 0, forward = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = ray_direction(*cam, Vec2(16.f * u01(rng), 16.f * u01(rng)));
    cap += d.y > 0.5f;
    forward += d.z > 0.f;  // a hemisphere
  }
  const double sigma = std::sqrt(n * 0.25 * 0.75);
  EXPECT_NEAR(cap, 0.25 * n, 4.4 * sigma);
  EXPECT_NEAR(forward, 0.5 * n, 4.4 * std::sqrt(n * 0.25));
}

// A wide pixel filter reaches past the film's edge: pbrt-v4 folds (u, v) back so that the map
// continues across its edges, and points just either side of an edge look the same way.
TEST(SphericalCamera, EqualAreaMapContinuesAcrossTheSquaresEdges) {
  const float e = 1e-3f;
  for (float t : {0.1f, 0.3f, 0.5f, 0.85f}) {
    for (auto [inside, outside] : {std::pair{Vec2(e, t), Vec2(-e, t)}, std::pair{Vec2(1 - e, t), Vec2(1 + e, t)},
                                   std::pair{Vec2(t, e), Vec2(t, -e)}, std::pair{Vec2(t, 1 - e), Vec2(t, 1 + e)}}) {
      const Vec2 w = wrap_equal_area_square(outside);
      EXPECT_TRUE(w.x >= 0.f && w.x <= 1.f && w.y >= 0.f && w.y <= 1.f);
      const Vec3 a = spherical_direction(SphericalMapping::EqualArea, inside);
      const Vec3 b = spherical_direction(SphericalMapping::EqualArea, outside);
      EXPECT_LT(glm::length(a - b), 1e-2f) << inside.x << " " << inside.y;
    }
  }
  // Inside the square nothing moves.
  EXPECT_EQ(wrap_equal_area_square(Vec2(0.3f, 0.8f)), Vec2(0.3f, 0.8f));
}

TEST(SphericalCamera, PlacedByTheCameraTransformWithShutterTimes) {
  const Transform world_from_camera = translate(Vec3(1, 2, 3)) * rotate(90, Vec3(1, 0, 0));
  ParameterList list;
  list.add(float_param("shutteropen", {2}));
  list.add(float_param("shutterclose", {4}));
  auto cam = create_spherical_camera(CameraContext{list, world_from_camera, IVec2(16, 16), "."});
  CameraSample cs;
  cs.p_film = Vec2(8.f);  // the camera's +y
  cs.time = 0.25f;
  auto r = cam->generate_ray(cs);
  ASSERT_TRUE(r);
  EXPECT_NEAR(glm::length(r->ray.o - Vec3(1, 2, 3)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(r->ray.d - world_from_camera.vector(Vec3(0, 1, 0))), 0.f, 1e-6f);
  EXPECT_FLOAT_EQ(r->ray.time, 2.5f);
}

TEST(SphericalCamera, UnknownMappingIsAnErrorAndLensParametersWarn) {
  try {
    make_camera({string_param("mapping", "cubemap")}, IVec2(8, 8));
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.pbrt:5:18"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mapping"), std::string::npos) << e.what();
  }
  const int before = warning_count();
  set_warnings_enabled(false);
  make_camera({float_param("lensradius", {0.1}), float_param("screenwindow", {-1, 1, -1, 1})}, IVec2(8, 8));
  set_warnings_enabled(true);
  EXPECT_EQ(warning_count(), before + 2);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
