// Spheres: hits against the analytic ray-sphere solution, partial spheres, far-away
// origins (the stable quadratic), pbrt's uv, validation, and area sampling by chi-square.
#include "shapes/sphere.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "../support/one_shape.h"
#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

ParameterList sphere_params(std::vector<std::pair<std::string, double>> floats) {
  return test::float_params("sphere.pbrt", 5, floats);
}

std::unique_ptr<Shape> make_sphere(std::vector<std::pair<std::string, double>> floats, const Transform& t = Transform(),
                                   bool reverse = false) {
  ParameterList pl = sphere_params(std::move(floats));
  auto shapes = create_sphere_shapes(ShapeContext{pl, t, reverse, ""});
  for (const Param& p : pl.params()) EXPECT_TRUE(p.used) << p.name;
  return std::move(shapes.at(0));
}

using test::expect_near;
using test::OneShape;
std::string error_of(const std::function<void()>& f) { return test::scene_error_of(f); }

TEST(Sphere, AxialHitAtAnalyticDistance) {
  OneShape s(make_sphere({}));
  auto si = s.hit(Vec3(0, 0, -5), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 4.f, 1e-6f);
  expect_near(si->p, Vec3(0, 0, -1), 1e-6f);
  expect_near(si->n, Vec3(0, 0, -1), 1e-6f);
  // pbrt: v = (theta - theta_zmin) / (theta_zmax - theta_zmin) = (pi - pi) / (0 - pi) = 0.
  EXPECT_NEAR(si->uv.y, 0.f, 1e-6f);
  EXPECT_EQ(si->ns, si->n);
}

TEST(Sphere, OffAxisHitPointNormalAndUV) {
  OneShape s(make_sphere({}));
  // x = 0.6 meets the unit sphere at z = -0.8 (3-4-5 triangle).
  auto si = s.hit(Vec3(0.6f, 0, -5), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 4.2f, 1e-6f);
  expect_near(si->p, Vec3(0.6f, 0, -0.8f), 1e-6f);
  expect_near(si->n, Vec3(0.6f, 0, -0.8f), 1e-6f);
  double theta = std::acos(-0.8);
  EXPECT_NEAR(si->uv.x, 0.f, 1e-6f);  // phi = 0
  EXPECT_NEAR(si->uv.y, float(1.0 - theta / kPiDouble), 1e-6f);
  // dp/du = phimax (-y, x, 0) = (0, 2 pi 0.6, 0); dp/dv = -pi (z cos phi, z sin phi, -r sin theta).
  expect_near(si->dpdu, Vec3(0, float(2 * kPiDouble * 0.6), 0), 1e-5f);
  expect_near(si->dpdv, Vec3(float(-kPiDouble * -0.8), 0, float(kPiDouble * 0.6)), 1e-5f);
  EXPECT_GT(glm::dot(glm::cross(si->dpdu, si->dpdv), si->n), 0.f);
}

TEST(Sphere, TransformedSphere) {
  Transform t = translate(Vec3(1, 2, 3)) * scale(Vec3(2, 2, 2));
  OneShape s(make_sphere({{"radius", 1.5}}, t));  // world radius 3 about (1, 2, 3)
  auto si = s.hit(Vec3(1, 2, -10), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 10.f, 1e-5f);
  expect_near(si->p, Vec3(1, 2, 0), 1e-5f);
  expect_near(si->n, Vec3(0, 0, -1), 1e-6f);
  EXPECT_NEAR(s.shape->area(), float(4 * kPiDouble * 9), 1e-3f);
  Bounds3 b = s.shape->bounds();
  EXPECT_NEAR(b.lo.x, -2.f, 1e-5f);
  EXPECT_NEAR(b.hi.z, 6.f, 1e-5f);
}

TEST(Sphere, GrazingRaysMissOrHitByDistance) {
  OneShape s(make_sphere({}));
  EXPECT_FALSE(s.hit(Vec3(1.001f, 0, -5), Vec3(0, 0, 1)));
  EXPECT_TRUE(s.hit(Vec3(0.999f, 0, -5), Vec3(0, 0, 1)));
  EXPECT_FALSE(s.hit(Vec3(0, 0, -5), Vec3(0, 0, -1)));       // pointing away
  EXPECT_FALSE(s.hit(Vec3(0, 0, -5), Vec3(0, 0, 1), 3.9f));  // tmax before the sphere
}

TEST(Sphere, OccludedRespectsTmax) {
  OneShape s(make_sphere({}));
  EXPECT_FALSE(s.scene->occluded(Ray{Vec3(0, 0, -5), Vec3(0, 0, 1), 3.9f}));
  EXPECT_TRUE(s.scene->occluded(Ray{Vec3(0, 0, -5), Vec3(0, 0, 1), 4.1f}));
  EXPECT_FALSE(s.scene->occluded(Ray{Vec3(0, 0, -5), Vec3(0, 0, -1)}));
}

TEST(Sphere, NoSliverLostAtPhiTwoPi) {
  // A cut sphere (zmax) runs the azimuth test; phi just below 2 pi must stay in.
  OneShape s(make_sphere({{"zmax", 0.5}}));
  EXPECT_TRUE(s.hit(Vec3(5, -1e-7f, 0), Vec3(-1, 0, 0)));
  EXPECT_TRUE(s.hit(Vec3(5, 0, 0), Vec3(-1, 0, 0)));
}

TEST(Sphere, RayFromInsideHitsFarSideWithOutwardNormal) {
  OneShape s(make_sphere({{"radius", 2}}));
  auto si = s.hit(Vec3(0), Vec3(0, 1, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 2.f, 1e-6f);
  expect_near(si->n, Vec3(0, 1, 0), 1e-6f);
}

TEST(Sphere, FarOriginKeepsPrecision) {
  // The textbook discriminant b^2 - 4ac cancels completely here (b^2 ~ 4e18 against a
  // difference of 4); the stable form recovers t = 1e9 - 1 exactly.
  Sphere sphere(Transform(), false, 1.0, -1.0, 1.0, 360.0);
  auto t = sphere.hit(Vec3(0, 0, -1e9f), Vec3(0, 0, 1), 0.0, 1e30);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 1e9 - 1.0, 1e-3);
  // Off axis by 0.6: z = -0.8, t = 1e9 - 0.8.
  t = sphere.hit(Vec3(0.6f, 0, -1e9f), Vec3(0, 0, 1), 0.0, 1e30);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 1e9 - 0.8, 1e-3);
  // A tiny sphere seen from far away (radius 1e-3 at distance 1e4).
  Sphere tiny(Transform(), false, 1e-3, -1e-3, 1e-3, 360.0);
  t = tiny.hit(Vec3(0.6e-3f, 0, -1e4f), Vec3(0, 0, 1), 0.0, 1e30);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 1e4 - 0.8e-3, 1e-7);
}

TEST(Sphere, PartialSphereTriesFarRootWhenNearIsCutAway) {
  OneShape s(make_sphere({{"zmax", 0.5}}));
  // From above: z = 1 is cut away, the ray enters the bowl and meets the inside at z = -1.
  auto si = s.hit(Vec3(0, 0, 5), Vec3(0, 0, -1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 6.f, 1e-6f);
  expect_near(si->n, Vec3(0, 0, -1), 1e-6f);  // still the outward normal
  // A ray whose both intersections lie above zmax misses.
  EXPECT_FALSE(s.hit(Vec3(0, -5, 0.9f), Vec3(0, 1, 0)));
}

TEST(Sphere, PhiMaxCutsAzimuth) {
  OneShape s(make_sphere({{"phimax", 180}}));
  // Near hit at phi = 270 degrees is cut away; far hit at phi = 90 degrees remains.
  auto si = s.hit(Vec3(0, -5, 0), Vec3(0, 1, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 6.f, 1e-6f);
  expect_near(si->p, Vec3(0, 1, 0), 1e-6f);
  EXPECT_NEAR(si->uv.x, 0.5f, 1e-6f);  // phi / phimax = 90 / 180
  // Along y = -0.5 both crossings (phi = 330 and 210 degrees) lie in the removed half.
  EXPECT_FALSE(s.hit(Vec3(5, -0.5f, 0), Vec3(-1, 0, 0)));
}

TEST(Sphere, PartialSphereUV) {
  OneShape s(make_sphere({{"zmin", -0.5}, {"zmax", 0.5}, {"phimax", 180}}));
  // Hit at (0, 1, 0): theta = pi/2 between theta(zmin) = 2pi/3 and theta(zmax) = pi/3: v = 1/2.
  auto si = s.hit(Vec3(0, 5, 0), Vec3(0, -1, 0));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(si->uv.y, 0.5f, 1e-6f);
  // Area phimax r (zmax - zmin) = pi * 1 * 1.
  EXPECT_NEAR(s.shape->area(), float(kPiDouble), 1e-5f);
}

TEST(Sphere, ReverseOrientationFlipsNormal) {
  OneShape s(make_sphere({}, Transform(), true));
  auto si = s.hit(Vec3(0, 0, -5), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  expect_near(si->n, Vec3(0, 0, 1), 1e-6f);
  ShapeSample smp = s.shape->sample_area(Vec2(0.3f, 0.7f));
  EXPECT_NEAR(glm::dot(smp.n, glm::normalize(smp.p)), -1.f, 1e-5f);
}

TEST(Sphere, MirrorTransformKeepsOutwardNormal) {
  // pbrt flips cross(dpdu, dpdv) for handedness-swapping transforms, which leaves the
  // normal pointing out of the sphere.
  OneShape s(make_sphere({}, scale(Vec3(-1, 1, 1))));
  auto si = s.hit(Vec3(0.6f, 0, -5), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  expect_near(si->n, Vec3(0.6f, 0, -0.8f), 1e-6f);
}

TEST(Sphere, ValidationErrorsNameTheParameter) {
  std::string e = error_of([] { make_sphere({{"radius", 0}}); });
  EXPECT_NE(e.find("\"radius\""), std::string::npos) << e;
  EXPECT_NE(e.find("sphere.pbrt:5:9"), std::string::npos) << e;
  e = error_of([] { make_sphere({{"phimax", 400}}); });
  EXPECT_NE(e.find("\"phimax\""), std::string::npos) << e;
  e = error_of([] { make_sphere({{"phimax", 0}}); });
  EXPECT_NE(e.find("\"phimax\""), std::string::npos) << e;
  e = error_of([] { make_sphere({{"zmin", 2}, {"zmax", 3}}); });
  EXPECT_NE(e.find("leaves nothing"), std::string::npos) << e;
}

TEST(Sphere, AreaSamplingUniformOverEqualAreaZones) {
  // Archimedes: bands of equal height have equal area. 10 bands x 4 quadrants = 40 cells
  // of equal probability; 39 dof, 0.1% critical value 72.05 (fixed seed).
  Transform t = translate(Vec3(3, -2, 1)) * rotate(30.f, Vec3(1, 1, 0)) * scale(Vec3(2, 2, 2));
  auto sphere = make_sphere({{"radius", 0.5}}, t);
  EXPECT_NEAR(sphere->area(), float(4 * kPiDouble), 1e-4f);  // world radius 1
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  const int n = 200000;
  std::vector<int> counts(40, 0);
  for (int i = 0; i < n; ++i) {
    ShapeSample s = sphere->sample_area(Vec2(std::min(U(rng), kOneMinusEpsilon), std::min(U(rng), kOneMinusEpsilon)));
    ASSERT_FLOAT_EQ(s.pdf_area, float(1.0 / (4 * kPiDouble)));
    Vec3 local = t.inverse().point(s.p) * 2.f;  // unit sphere coordinates
    ASSERT_NEAR(glm::length(local), 1.f, 1e-5f);
    ASSERT_NEAR(glm::dot(s.n, glm::normalize(s.p - Vec3(3, -2, 1))), 1.f, 1e-5f);
    int band = std::min(9, int((local.z + 1.f) * 5.f));
    int quadrant = (local.x >= 0 ? 0 : 1) + (local.y >= 0 ? 0 : 2);
    ++counts[band * 4 + quadrant];
  }
  double chi2 = 0.0, e = n / 40.0;
  for (int c : counts) chi2 += (c - e) * (c - e) / e;
  EXPECT_LT(chi2, 72.05);
}

TEST(Sphere, PartialSphereSamplesStayOnThePart) {
  auto sphere = make_sphere({{"zmin", -0.2}, {"zmax", 0.7}, {"phimax", 90}});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  const int n = 50000;
  std::vector<int> counts(3, 0);  // three bands of height 0.3: equal areas
  for (int i = 0; i < n; ++i) {
    Vec3 p = sphere->sample_area(Vec2(std::min(U(rng), kOneMinusEpsilon), std::min(U(rng), kOneMinusEpsilon))).p;
    ASSERT_GE(p.z, -0.2f - 1e-6f);
    ASSERT_LE(p.z, 0.7f + 1e-6f);
    ASSERT_GE(p.x, -1e-6f);
    ASSERT_GE(p.y, -1e-6f);
    ++counts[std::clamp(int((p.z + 0.2f) / 0.3f), 0, 2)];
  }
  double chi2 = 0.0, e = n / 3.0;
  for (int c : counts) chi2 += (c - e) * (c - e) / e;
  EXPECT_LT(chi2, 13.82);  // 2 dof, alpha 0.001
  EXPECT_NEAR(sphere->area(), float(0.5 * kPiDouble * 0.9), 1e-5f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
