// Disks: hits against the analytic ray-plane solution, annulus and wedge cuts, pbrt's uv,
// orientation, exact areas under any affine transform, and area sampling by chi-square.
#include "shapes/disk.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "../support/one_shape.h"
#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Shape> make_disk(std::vector<std::pair<std::string, double>> floats, const Transform& t = Transform(),
                                 bool reverse = false) {
  ParameterList pl = test::float_params("disk.pbrt", 2, floats);
  auto shapes = create_disk_shapes(ShapeContext{pl, t, reverse, ""});
  return std::move(shapes.at(0));
}

using test::expect_near;
using test::OneShape;
std::string error_of(const std::function<void()>& f) { return test::scene_error_of(f); }

TEST(Disk, HitPointNormalAndUV) {
  OneShape s(make_disk({{"height", 1}}));
  auto si = s.hit(Vec3(0.3f, 0.4f, 5), Vec3(0, 0, -1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 4.f, 1e-6f);
  expect_near(si->p, Vec3(0.3f, 0.4f, 1), 1e-6f);
  expect_near(si->n, Vec3(0, 0, 1), 1e-6f);
  // u = phi / 2pi, v = (radius - r_hit) / (radius - innerradius) = 0.5.
  EXPECT_NEAR(si->uv.x, float(std::atan2(0.4, 0.3) / (2 * kPiDouble)), 1e-6f);
  EXPECT_NEAR(si->uv.y, 0.5f, 1e-6f);
  // pbrt: dp/du = phimax (-y, x, 0), dp/dv = (x, y, 0) (ri - r) / r_hit.
  expect_near(si->dpdu, Vec3(float(-2 * kPiDouble * 0.4), float(2 * kPiDouble * 0.3), 0), 1e-5f);
  expect_near(si->dpdv, Vec3(-0.6f, -0.8f, 0), 1e-6f);
}

TEST(Disk, HitFromBelowKeepsNormalAndCentreHasFrame) {
  OneShape s(make_disk({}));
  auto si = s.hit(Vec3(0, 0, -2), Vec3(0, 0, 1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 2.f, 1e-6f);
  expect_near(si->n, Vec3(0, 0, 1), 1e-6f);
  // At the centre pbrt's dp/dv is 0/0; the frame must still be usable.
  Vec3 c = glm::cross(si->dpdu, si->dpdv);
  EXPECT_GT(glm::length(c), 0.f);
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

TEST(Disk, MissesOutsideInsideAndParallel) {
  OneShape s(make_disk({{"radius", 2}, {"innerradius", 1}, {"phimax", 90}}));
  EXPECT_TRUE(s.hit(Vec3(1, 1, 1), Vec3(0, 0, -1)));
  EXPECT_FALSE(s.hit(Vec3(0.5f, 0.5f, 1), Vec3(0, 0, -1)));  // in the hole
  EXPECT_FALSE(s.hit(Vec3(1.5f, 1.5f, 1), Vec3(0, 0, -1)));  // beyond the rim (r = 2.12)
  EXPECT_FALSE(s.hit(Vec3(-1, 1, 1), Vec3(0, 0, -1)));       // phi = 135 > 90 degrees
  EXPECT_FALSE(s.hit(Vec3(-3, 1, 0), Vec3(1, 0, 0)));        // in the plane: grazes
  EXPECT_FALSE(s.hit(Vec3(-3, 1, 0.5f), Vec3(1, 0, 0)));     // parallel above
}

TEST(Disk, ReverseOrientationAndMirror) {
  OneShape rev(make_disk({}, Transform(), true));
  auto si = rev.hit(Vec3(0.1f, 0, 1), Vec3(0, 0, -1));
  ASSERT_TRUE(si);
  expect_near(si->n, Vec3(0, 0, -1), 1e-6f);
  EXPECT_NEAR(rev.shape->sample_area(Vec2(0.5f)).n.z, -1.f, 1e-6f);
  // A z mirror turns the object's +z face to -z (pbrt: cross product plus handedness flip).
  OneShape mirrored(make_disk({{"height", 1}}, scale(Vec3(1, 1, -1))));
  si = mirrored.hit(Vec3(0.1f, 0, 1), Vec3(0, 0, -1));
  ASSERT_TRUE(si);
  EXPECT_NEAR(si->t, 2.f, 1e-6f);  // plane z = -1
  expect_near(si->n, Vec3(0, 0, -1), 1e-6f);
}

TEST(Disk, AreaExactUnderAffineTransforms) {
  // Annulus wedge: phimax/2 (r^2 - ri^2) = (pi/2)/2 (4 - 1) = 3pi/4.
  EXPECT_NEAR(make_disk({{"radius", 2}, {"innerradius", 1}, {"phimax", 90}})->area(), float(0.75 * kPiDouble), 1e-5f);
  // Scaling x by 2 and y by 3 scales every plane area by 6; z scale leaves it alone.
  EXPECT_NEAR(make_disk({}, scale(Vec3(2, 3, 5)))->area(), float(6 * kPiDouble), 1e-4f);
  // The plane x = const after a rotation: an ellipse with semi-axes 1 and 4.
  EXPECT_NEAR(make_disk({}, scale(Vec3(1, 4, 1)) * rotate(90.f, Vec3(0, 1, 0)))->area(), float(4 * kPiDouble), 1e-4f);
}

TEST(Disk, AreaSamplingUniformOverEqualAreaCells) {
  // Annulus r in [0.5, 1]: equal steps in r^2 give equal-area rings; 5 rings x 6 sectors
  // (phimax 300) = 30 cells; 29 dof, 0.1% critical value 58.30 (fixed seed). The non-uniform
  // in-plane scale keeps uniformity (affine maps keep area ratios within a plane).
  Transform t = translate(Vec3(0, 0, 2)) * scale(Vec3(3, 1.5f, 1));
  auto disk = make_disk({{"radius", 1}, {"innerradius", 0.5}, {"phimax", 300}}, t);
  float area = float(0.5 * (300.0 / 180.0 * kPiDouble) * 0.75 * 4.5);
  EXPECT_NEAR(disk->area(), area, 1e-4f);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  const int n = 150000;
  std::vector<int> counts(30, 0);
  for (int i = 0; i < n; ++i) {
    ShapeSample s = disk->sample_area(Vec2(std::min(U(rng), kOneMinusEpsilon), std::min(U(rng), kOneMinusEpsilon)));
    ASSERT_FLOAT_EQ(s.pdf_area, 1.f / area);
    ASSERT_NEAR(s.p.z, 2.f, 1e-6f);
    Vec3 local = t.inverse().point(s.p);
    float r2 = local.x * local.x + local.y * local.y;
    double phi = std::atan2(local.y, local.x);
    if (phi < 0) phi += 2 * kPiDouble;
    ASSERT_GE(r2, 0.25f - 1e-5f);
    ASSERT_LE(r2, 1.f + 1e-5f);
    int ring = std::clamp(int((r2 - 0.25f) / 0.15f), 0, 4);
    int sector = std::clamp(int(phi / (50.0 / 180.0 * kPiDouble)), 0, 5);
    ++counts[ring * 6 + sector];
  }
  double chi2 = 0.0, e = n / 30.0;
  for (int c : counts) chi2 += (c - e) * (c - e) / e;
  EXPECT_LT(chi2, 58.30);
}

TEST(Disk, ValidationErrorsNameTheParameter) {
  std::string e = error_of([] { make_disk({{"radius", -1}}); });
  EXPECT_NE(e.find("\"radius\""), std::string::npos) << e;
  e = error_of([] { make_disk({{"innerradius", 1}}); });
  EXPECT_NE(e.find("\"innerradius\""), std::string::npos) << e;
  EXPECT_NE(e.find("disk.pbrt:2:9"), std::string::npos) << e;
  e = error_of([] { make_disk({{"phimax", -10}}); });
  EXPECT_NE(e.find("\"phimax\""), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
