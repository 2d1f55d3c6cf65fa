// Cylinders (pbrt-v4's open tube): hits against the analytic ray-cylinder solution, the inside
// of the tube through the open ends, the z and azimuth cuts, pbrt's uv and tangents, the
// outward normal and ReverseOrientation, a far origin, the area, area sampling by chi-square,
// millions of random rays (no NaN, every hit on the surface) and parameter errors.
#include "shapes/cylinder.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "../support/one_shape.h"
#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Shape> make_cylinder(std::vector<std::pair<std::string, double>> floats,
                                     const Transform& t = Transform(), bool reverse = false) {
  ParameterList pl = test::float_params("cyl.pbrt", 3, floats);
  auto shapes = create_cylinder_shapes(ShapeContext{pl, t, reverse, ""});
  return std::move(shapes.at(0));
}

using test::expect_near;
using test::OneShape;

TEST(Cylinder, HitPointNormalUVAndTangents) {
  OneShape s(make_cylinder({{"radius", 2}, {"zmin", -1}, {"zmax", 3}}));
  // From x = 5 towards -x at y = 1.2, z = 0.5: enters at x = sqrt(4 - 1.44) = 1.6.
  auto si = s.hit(Vec3(5, 1.2f, 0.5f), Vec3(-1, 0, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 5.f - 1.6f, 1e-5f);
  expect_near(si->p, Vec3(1.6f, 1.2f, 0.5f), 1e-5f);
  expect_near(si->n, Vec3(0.8f, 0.6f, 0), 1e-5f);
  const double phi = std::atan2(1.2, 1.6);
  EXPECT_NEAR(si->uv.x, float(phi / (2 * kPiDouble)), 1e-6f);
  EXPECT_NEAR(si->uv.y, (0.5f + 1.f) / 4.f, 1e-6f);
  // pbrt: dp/du = phimax (-y, x, 0), dp/dv = (0, 0, zmax - zmin).
  expect_near(si->dpdu, Vec3(float(-2 * kPiDouble * 1.2), float(2 * kPiDouble * 1.6), 0), 1e-4f);
  expect_near(si->dpdv, Vec3(0, 0, 4), 1e-6f);
}

TEST(Cylinder, InsideThroughTheOpenEndAndFromWithin) {
  OneShape s(make_cylinder({}));
  // Down the open top end at a slant: the near root is above zmax, the far one is the inside wall.
  auto si = s.hit(Vec3(0, 0, 2), glm::normalize(Vec3(1, 0, -1)));
  ASSERT_TRUE(si);
  expect_near(si->p, Vec3(1, 0, 1), 1e-5f);
  expect_near(si->n, Vec3(1, 0, 0), 1e-5f);  // outward, whichever side the ray came from
  // From the axis: the far root only.
  si = s.hit(Vec3(0, 0, 0), Vec3(0, -1, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 1.f, 1e-6f);
}

TEST(Cylinder, MissesAboveBesideAlongTheAxisAndInTheCut) {
  OneShape s(make_cylinder({{"phimax", 180}}));
  EXPECT_FALSE(s.hit(Vec3(5, 0.5f, 1.5f), Vec3(-1, 0, 0)));  // above zmax
  EXPECT_FALSE(s.hit(Vec3(5, 1.5f, 0), Vec3(-1, 0, 0)));     // beside
  EXPECT_FALSE(s.hit(Vec3(0.5f, 0.5f, 5), Vec3(0, 0, -1)));  // along the axis, inside
  EXPECT_FALSE(s.hit(Vec3(1, 0, 5), Vec3(0, 0, -1)));        // along the surface: grazes
  // phimax 180 keeps y >= 0: a ray along -x at y = -0.5 meets only the cut half... of nothing.
  EXPECT_FALSE(s.hit(Vec3(5, -0.5f, 0), Vec3(-1, 0, 0)));
  // At y = +0.5 it meets the kept half twice; the first is x = +sqrt(0.75).
  auto si = s.hit(Vec3(5, 0.5f, 0), Vec3(-1, 0, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->p.x, std::sqrt(0.75f), 1e-5f);
}

TEST(Cylinder, ReverseOrientationAndFarOrigin) {
  OneShape rev(make_cylinder({}, Transform(), true));
  auto si = rev.hit(Vec3(5, 0, 0), Vec3(-1, 0, 0));
  ASSERT_TRUE(si);
  expect_near(si->n, Vec3(-1, 0, 0), 1e-6f);
  // 1e5 units away (rotated and moved): the hit still lies on the tube within float rounding.
  const Transform placed = translate(Vec3(3, -2, 7)) * rotate(30.f, Vec3(1, 1, 0));
  OneShape far(make_cylinder({{"radius", 0.5}}, placed));
  const Vec3 target = placed.point(Vec3(0.5f, 0, 0.2f));
  const Vec3 o = target + Vec3(1e5f, 3e4f, -2e4f);
  si = far.hit(o, glm::normalize(target - o));
  ASSERT_TRUE(si);
  const Vec3 local = placed.inverse().point(si->p);
  EXPECT_NEAR(std::hypot(local.x, local.y), 0.5f, 1e-3f);
}

TEST(Cylinder, AreaAndUniformAreaSampling) {
  auto c = make_cylinder({{"radius", 2}, {"zmin", 0}, {"zmax", 3}, {"phimax", 270}});
  const float area = float(1.5 * kPiDouble * 2 * 3);
  EXPECT_NEAR(c->area(), area, 1e-4f);
  // 6 z bands x 6 sectors of equal area; 35 dof, 0.1 % critical value 66.62 (fixed seed).
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> U(0.f, kOneMinusEpsilon);
  const int n = 120000;
  std::vector<int> counts(36, 0);
  for (int i = 0; i < n; ++i) {
    const ShapeSample s = c->sample_area(Vec2(U(rng), U(rng)));
    ASSERT_FLOAT_EQ(s.pdf_area, 1.f / area);
    ASSERT_NEAR(std::hypot(s.p.x, s.p.y), 2.f, 1e-5f);
    expect_near(s.n, Vec3(s.p.x / 2, s.p.y / 2, 0), 1e-5f);
    double phi = std::atan2(s.p.y, s.p.x);
    if (phi < 0) phi += 2 * kPiDouble;
    ++counts[std::clamp(int(s.p.z / 0.5f), 0, 5) * 6 + std::clamp(int(phi / (45.0 / 180.0 * kPiDouble)), 0, 5)];
  }
  double chi2 = 0.0, e = n / 36.0;
  for (int k : counts) chi2 += (k - e) * (k - e) / e;
  EXPECT_LT(chi2, 66.62);
}

TEST(Cylinder, MillionsOfRandomRaysGiveFinitePointsOnTheSurface) {
  OneShape s(make_cylinder({{"radius", 1.5}, {"zmin", -0.5}, {"zmax", 2}, {"phimax", 300}}));
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> U(-4.f, 4.f);
  int hits = 0;
  for (int i = 0; i < 2000000; ++i) {
    const Vec3 o(U(rng), U(rng), U(rng)), d(U(rng), U(rng), U(rng));
    if (!(glm::dot(d, d) > 1e-6f)) continue;
    auto si = s.hit(o, glm::normalize(d));
    if (!si) continue;
    ++hits;
    ASSERT_TRUE(std::isfinite(si->p.x) && std::isfinite(si->n.x) && std::isfinite(si->uv.x) &&
                std::isfinite(si->dpdu.x));
    ASSERT_NEAR(std::hypot(si->p.x, si->p.y), 1.5f, 1e-4f);
    ASSERT_GE(si->p.z, -0.5f - 1e-4f);
    ASSERT_LE(si->p.z, 2.f + 1e-4f);
  }
  EXPECT_GT(hits, 100000);
}

TEST(Cylinder, ValidationErrorsNameTheParameter) {
  auto error_of = [](const std::function<void()>& f) { return test::scene_error_of(f); };
  std::string e = error_of([] { make_cylinder({{"radius", 0}}); });
  EXPECT_NE(e.find("\"radius\""), std::string::npos) << e;
  e = error_of([] { make_cylinder({{"zmin", 1}, {"zmax", 1}}); });
  EXPECT_NE(e.find("\"zmax\""), std::string::npos) << e;
  EXPECT_NE(e.find("cyl.pbrt:3"), std::string::npos) << e;
  e = error_of([] { make_cylinder({{"phimax", 400}}); });
  EXPECT_NE(e.find("\"phimax\""), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
