// The environment-map layouts: the equal-area map sends the image centre, corners and edge
// midpoints where Clarberg's construction says, inverts exactly, and preserves area (uniform
// points in the square land uniformly on the sphere: chi-square in z and phi, 1%).
// The lat-long map follows pbrt-v3's convention (top row +z, u = phi / 2 pi).
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "light_test_util.h"
#include "lights/sphere_mapping.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

void expect_dir(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-5f);
  EXPECT_NEAR(got.y, want.y, 1e-5f);
  EXPECT_NEAR(got.z, want.z, 1e-5f);
}

TEST(EqualAreaMapping, LandmarksAsInClarberg) {
  expect_dir(equal_area_square_to_sphere(Vec2(0.5f, 0.5f)), Vec3(0, 0, 1));
  for (Vec2 corner : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)})
    expect_dir(equal_area_square_to_sphere(corner), Vec3(0, 0, -1));
  expect_dir(equal_area_square_to_sphere(Vec2(1.f, 0.5f)), Vec3(1, 0, 0));
  expect_dir(equal_area_square_to_sphere(Vec2(0.f, 0.5f)), Vec3(-1, 0, 0));
  expect_dir(equal_area_square_to_sphere(Vec2(0.5f, 1.f)), Vec3(0, 1, 0));
  expect_dir(equal_area_square_to_sphere(Vec2(0.5f, 0.f)), Vec3(0, -1, 0));
  // The diamond |2u-1| + |2v-1| = 1 is the horizon.
  EXPECT_NEAR(equal_area_square_to_sphere(Vec2(0.75f, 0.75f)).z, 0.f, 1e-6f);
}

TEST(EqualAreaMapping, UnitLengthAndRoundTrip) {
  Uniform rng(1);
  for (int k = 0; k < 20000; ++k) {
    Vec2 p = rng.next2();
    Vec3 w = equal_area_square_to_sphere(p);
    ASSERT_NEAR(glm::length(w), 1.f, 1e-5f);
    Vec2 back = equal_area_sphere_to_square(w);
    ASSERT_NEAR(back.x, p.x, 2e-5f) << p.x << " " << p.y;
    ASSERT_NEAR(back.y, p.y, 2e-5f) << p.x << " " << p.y;
  }
}

// Archimedes: z and phi of a uniform point on the sphere are independent and uniform.
TEST(EqualAreaMapping, PreservesAreaChiSquare) {
  const int nz = 20, nphi = 20, n = 400000;
  std::vector<double> observed(nz * nphi, 0.0), expected(nz * nphi, double(n) / (nz * nphi));
  Uniform rng(2);
  for (int k = 0; k < n; ++k) {
    Vec3 w = equal_area_square_to_sphere(rng.next2());
    int iz = std::clamp(int((w.z + 1.f) * 0.5f * nz), 0, nz - 1);
    float phi = std::atan2(w.y, w.x) + kPi;
    int ip = std::clamp(int(phi / (2.f * kPi) * nphi), 0, nphi - 1);
    observed[iz * nphi + ip] += 1.0;
  }
  ChiSquareResult r = chi_square(observed, expected);
  EXPECT_GT(r.p_value, 0.01) << "chi2 " << r.statistic;
}

TEST(LatLongMapping, PbrtV3Convention) {
  expect_dir(latlong_square_to_sphere(Vec2(0.3f, 0.f)), Vec3(0, 0, 1));    // top row: +z
  expect_dir(latlong_square_to_sphere(Vec2(0.3f, 1.f)), Vec3(0, 0, -1));   // bottom row: -z
  expect_dir(latlong_square_to_sphere(Vec2(0.f, 0.5f)), Vec3(1, 0, 0));    // phi = 0
  expect_dir(latlong_square_to_sphere(Vec2(0.25f, 0.5f)), Vec3(0, 1, 0));  // phi = pi/2
  Vec2 uv = latlong_sphere_to_square(glm::normalize(Vec3(-1, -1, 1)));
  EXPECT_NEAR(uv.x, 5.f / 8.f, 1e-6f);  // phi = 5 pi / 4
  EXPECT_NEAR(uv.y, std::acos(1.f / std::sqrt(3.f)) / kPi, 1e-6f);
}

TEST(LatLongMapping, RoundTrip) {
  Uniform rng(4);
  for (int k = 0; k < 20000; ++k) {
    Vec2 p = rng.next2();
    p.y = 0.001f + 0.998f * p.y;  // phi is undefined at the poles
    Vec2 back = latlong_sphere_to_square(latlong_square_to_sphere(p));
    ASSERT_NEAR(back.x, p.x, 1e-5f);
    ASSERT_NEAR(back.y, p.y, 1e-5f);
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
