// core/transform: each constructor checked against its analytic matrix action, and every
// stored inverse against the product with its forward matrix.
#include "core/transform.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

void expect_vec_near(const Vec3& got, const Vec3& want, float tol = 1e-5f) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// The stored inverse must really be the inverse.
void expect_inverse_consistent(const Transform& t, float tol = 1e-5f) {
  Mat4 p = t.matrix() * t.inverse_matrix();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(p[c][r], c == r ? 1.f : 0.f, tol) << c << "," << r;
}

TEST(Transform, DefaultIsIdentity) {
  Transform t;
  EXPECT_TRUE(t.is_identity());
  EXPECT_FALSE(t.swaps_handedness());
  EXPECT_EQ(t.point(Vec3(1, 2, 3)), Vec3(1, 2, 3));
}

TEST(Transform, TranslateMovesPointsNotVectors) {
  Transform t = translate(Vec3(1, -2, 3));
  EXPECT_EQ(t.point(Vec3(0.f)), Vec3(1, -2, 3));
  EXPECT_EQ(t.vector(Vec3(1, 1, 1)), Vec3(1, 1, 1));
  EXPECT_EQ(t.normal(Vec3(0, 0, 1)), Vec3(0, 0, 1));
  EXPECT_EQ(t.inverse().point(Vec3(1, -2, 3)), Vec3(0.f));
  expect_inverse_consistent(t);
}

TEST(Transform, ScaleKeepsNormalsPerpendicular) {
  // Plane x + y = 0 (normal (1,1,0), tangent (1,-1,0)) under scale (2,1,1) becomes
  // x + 2y = 0, whose normal is along (1,2,0).
  Transform t = scale(Vec3(2, 1, 1));
  Vec3 n = t.normal(Vec3(1, 1, 0));
  Vec3 tangent = t.vector(Vec3(1, -1, 0));
  EXPECT_NEAR(glm::dot(n, tangent), 0.f, 1e-6f);
  expect_vec_near(glm::normalize(n), glm::normalize(Vec3(1, 2, 0)));
  expect_inverse_consistent(t);
  EXPECT_FALSE(t.swaps_handedness());
  EXPECT_TRUE(scale(Vec3(-1, 1, 1)).swaps_handedness());
  EXPECT_FALSE(scale(Vec3(-1, -1, 1)).swaps_handedness());
}

TEST(Transform, RotateFollowsTheRightHandRule) {
  expect_vec_near(rotate(90, Vec3(0, 0, 1)).point(Vec3(1, 0, 0)), Vec3(0, 1, 0));
  expect_vec_near(rotate(90, Vec3(1, 0, 0)).point(Vec3(0, 1, 0)), Vec3(0, 0, 1));
  expect_vec_near(rotate(90, Vec3(0, 1, 0)).point(Vec3(0, 0, 1)), Vec3(1, 0, 0));
  // 120 degrees about the (unnormalised) diagonal cycles the axes x -> y -> z -> x.
  Transform r = rotate(120, Vec3(2, 2, 2));
  expect_vec_near(r.vector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
  expect_vec_near(r.vector(Vec3(0, 1, 0)), Vec3(0, 0, 1));
  expect_vec_near(r.vector(Vec3(0, 0, 1)), Vec3(1, 0, 0));
  expect_inverse_consistent(r);
  expect_vec_near(r.inverse().vector(Vec3(0, 1, 0)), rotate(-120, Vec3(1, 1, 1)).vector(Vec3(0, 1, 0)));
  EXPECT_FALSE(r.swaps_handedness());
}

TEST(Transform, CompositionAppliesTheRightFactorFirst) {
  Transform t = translate(Vec3(1, 0, 0)) * scale(Vec3(2, 2, 2));
  EXPECT_EQ(t.point(Vec3(1, 1, 1)), Vec3(3, 2, 2));  // scaled, then translated
  expect_inverse_consistent(t);
  expect_vec_near(t.inverse().point(Vec3(3, 2, 2)), Vec3(1, 1, 1));
}

TEST(Transform, LookAtMapsEyeToOriginAndTargetToPlusZ) {
  Transform camera_from_world = look_at(Vec3(1, 2, 3), Vec3(1, 2, 10), Vec3(0, 1, 0));
  expect_vec_near(camera_from_world.point(Vec3(1, 2, 3)), Vec3(0, 0, 0));
  expect_vec_near(camera_from_world.point(Vec3(1, 2, 10)), Vec3(0, 0, 7));
  expect_vec_near(camera_from_world.vector(Vec3(0, 1, 0)), Vec3(0, 1, 0));
  // right = up x forward = (0,1,0) x (0,0,1) = (1,0,0)
  expect_vec_near(camera_from_world.inverse().vector(Vec3(1, 0, 0)), Vec3(1, 0, 0));
  expect_inverse_consistent(camera_from_world);
  // A tilted up vector only fixes the roll: the camera's +y stays perpendicular to the view.
  Transform tilted = look_at(Vec3(0.f), Vec3(0, 0, 1), Vec3(0, 1, 1));
  expect_vec_near(tilted.inverse().vector(Vec3(0, 1, 0)), Vec3(0, 1, 0));
}

TEST(Transform, LookAtRejectsDegenerateFrames) {
  EXPECT_THROW(look_at(Vec3(1.f), Vec3(1.f), Vec3(0, 1, 0)), std::domain_error);
  EXPECT_THROW(look_at(Vec3(0.f), Vec3(0, 3, 0), Vec3(0, 1, 0)), std::domain_error);
}

TEST(Transform, PerspectiveMapsNearFarAndFieldOfView) {
  // fov 90: tan(45) = 1, so a point at 45 degrees off-axis lands on the screen edge.
  Transform p = perspective(90.f, 1.f, 10.f);
  EXPECT_NEAR(p.point(Vec3(0, 0, 1)).z, 0.f, 1e-6f);
  EXPECT_NEAR(p.point(Vec3(0, 0, 10)).z, 1.f, 1e-6f);
  expect_vec_near(p.point(Vec3(1, 0, 1)), Vec3(1, 0, 0));
  // Depth 2: x,y divide by z; z = f/(f-n) * (1 - n/z) = 10/9 * 1/2.
  expect_vec_near(p.point(Vec3(0, 0.5f, 2)), Vec3(0, 0.25f, 5.f / 9.f));
  // fov 60: screen x = x / (z tan 30).
  EXPECT_NEAR(perspective(60.f, 0.1f, 100.f).point(Vec3(1, 0, 4)).x, 1.f / (4.f * std::tan(radians(30.f))), 1e-5f);
}

TEST(Transform, GeneralMatrixComputesItsInverse) {
  Mat4 m(1.f);
  m[0] = Vec4(2, 1, 0, 0);
  m[1] = Vec4(0, 3, 1, 0);
  m[2] = Vec4(1, 0, 4, 0);
  m[3] = Vec4(5, 6, 7, 1);
  Transform t(m);
  expect_inverse_consistent(t);
  EXPECT_THROW(Transform(Mat4(0.f)), std::domain_error);
  Mat4 rank2(1.f);
  rank2[2] = Vec4(1, 1, 0, 0);  // third column in the span of the first two
  EXPECT_THROW((Transform(rank2)), std::domain_error);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
