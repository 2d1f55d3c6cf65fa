// core/animated_transform: the interpolated transform against analytic motions (a rotation's
// angle grows linearly in time, a translation and a uniform scale lerp), pbrt-v4's boundary
// rules for times outside [start, end] (util/transform.cpp, AnimatedTransform::Interpolate),
// and the Embree keyframes rebuilt here from Embree's documented formula M = T R S.
#include "core/animated_transform.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

void expect_matrix_near(const Mat4& got, const Mat4& want, float tol = 2e-5f) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], want[c][r], tol) << "column " << c << " row " << r;
}

const Vec3 kZ(0.f, 0.f, 1.f);

TEST(AnimatedTransform, EqualKeyframesAreNotAnimated) {
  Transform t = translate(Vec3(1, 2, 3)) * rotate(30, Vec3(1, 1, 0));
  AnimatedTransform a(t, 0.f, t, 1.f);
  EXPECT_FALSE(a.is_animated());
  EXPECT_EQ(a.interpolate(0.5f).matrix(), t.matrix());
}

TEST(AnimatedTransform, RotationAngleGrowsLinearlyInTime) {
  AnimatedTransform a(Transform(), 0.f, rotate(90, kZ), 1.f);
  ASSERT_TRUE(a.is_animated());
  for (float u : {0.1f, 0.25f, 0.5f, 0.8f}) expect_matrix_near(a.interpolate(u).matrix(), rotate(90 * u, kZ).matrix());
}

TEST(AnimatedTransform, RotationTakesTheShorterWayRound) {
  // 10 degrees to 350 degrees: the shorter way passes 0, not 180.
  AnimatedTransform a(rotate(10, kZ), 0.f, rotate(350, kZ), 1.f);
  expect_matrix_near(a.interpolate(0.5f).matrix(), Mat4(1.f));
  expect_matrix_near(a.interpolate(0.25f).matrix(), rotate(5, kZ).matrix());
}

TEST(AnimatedTransform, TranslationAndUniformScaleLerpUnderRotation) {
  // pbrt-v4's polar decomposition and this Q R factorisation agree here: R(t) = rotation by
  // 60 t degrees, scale 1 + 2 t, translation (1 - t) a + t b.
  const Vec3 a(1, 0, -2), b(-3, 4, 0), axis = glm::normalize(Vec3(1, 2, 3));
  AnimatedTransform m(translate(a), 2.f, translate(b) * rotate(60, axis) * scale(Vec3(3.f)), 4.f);
  for (float u : {0.2f, 0.5f, 0.7f}) {
    Transform want = translate((1 - u) * a + u * b) * rotate(60 * u, axis) * scale(Vec3(1 + 2 * u));
    expect_matrix_near(m.interpolate(2.f + 2.f * u).matrix(), want.matrix(), 1e-4f);
  }
}

TEST(AnimatedTransform, HoldsTheKeyframesOutsideTheInterval) {
  Transform s = translate(Vec3(1, 0, 0)), e = translate(Vec3(0, 5, 0));
  AnimatedTransform a(s, 1.f, e, 3.f);
  EXPECT_EQ(a.interpolate(-10.f).matrix(), s.matrix());
  EXPECT_EQ(a.interpolate(1.f).matrix(), s.matrix());
  EXPECT_EQ(a.interpolate(3.f).matrix(), e.matrix());
  EXPECT_EQ(a.interpolate(7.f).matrix(), e.matrix());
  EXPECT_FLOAT_EQ(a.fraction(2.5f), 0.75f);
}

// pbrt-v4 checks nothing about TransformTimes: with end <= start, Interpolate returns the
// start transform up to and including start_time and the end transform after it.
TEST(AnimatedTransform, ReversedOrEqualTimesStepFromStartToEndAfterTheStartTime) {
  Transform s = translate(Vec3(1, 0, 0)), e = translate(Vec3(0, 5, 0));
  AnimatedTransform reversed(s, 2.f, e, 1.f);
  EXPECT_EQ(reversed.interpolate(1.5f).matrix(), s.matrix());
  EXPECT_EQ(reversed.interpolate(2.f).matrix(), s.matrix());
  EXPECT_EQ(reversed.interpolate(2.5f).matrix(), e.matrix());
  AnimatedTransform equal(s, 0.f, e, 0.f);
  EXPECT_EQ(equal.interpolate(0.f).matrix(), s.matrix());
  EXPECT_EQ(equal.interpolate(0.25f).matrix(), e.matrix());
  EXPECT_EQ(equal.fraction(0.25f), 1.f);
}

// Embree's documented meaning of RTCQuaternionDecomposition: M = T R S, S upper triangular
// (scale on the diagonal, skew_ab at row a column b), R the unit quaternion r + i i + j j + k k.
Mat4 embree_matrix(const RTCQuaternionDecomposition& d) {
  const float r = d.quaternion_r, i = d.quaternion_i, j = d.quaternion_j, k = d.quaternion_k;
  const float rot[3][3] = {{1 - 2 * (j * j + k * k), 2 * (i * j - r * k), 2 * (i * k + r * j)},
                           {2 * (i * j + r * k), 1 - 2 * (i * i + k * k), 2 * (j * k - r * i)},
                           {2 * (i * k - r * j), 2 * (j * k + r * i), 1 - 2 * (i * i + j * j)}};
  const float s[3][3] = {{d.scale_x, d.skew_xy, d.skew_xz}, {0, d.scale_y, d.skew_yz}, {0, 0, d.scale_z}};
  Mat4 m(1.f);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      float v = 0.f;
      for (int k2 = 0; k2 < 3; ++k2) v += rot[row][k2] * s[k2][col];
      m[col][row] = v;
    }
    m[3][row] = (&d.translation_x)[row];
  }
  return m;
}

TEST(AnimatedTransform, EmbreeKeyframesRebuildBothTransformsWithShearAndMirror) {
  Mat4 shear(1.f);
  shear[1][0] = 0.7f;   // x += 0.7 y
  shear[2][1] = -0.4f;  // y -= 0.4 z
  Transform start = translate(Vec3(2, -1, 0.5f)) * rotate(33, Vec3(1, -2, 0.5f)) * Transform(shear) *
                    scale(Vec3(2, 0.5f, -1.5f));  // mirrored
  Transform end = rotate(-70, Vec3(0, 1, 1)) * scale(Vec3(1, 3, -0.25f));
  AnimatedTransform a(start, 0.f, end, 1.f);
  expect_matrix_near(embree_matrix(a.embree_keyframe(0)), start.matrix(), 1e-5f);
  expect_matrix_near(embree_matrix(a.embree_keyframe(1)), end.matrix(), 1e-5f);
  // In between, the same blend Embree makes: lerped T and S, slerped R.
  for (float u : {0.1f, 0.5f, 0.9f}) {
    Transform mid = a.at_fraction(u);
    EXPECT_LT(glm::determinant(glm::mat3(mid.matrix())), 0.f);                  // still mirrored, never flat
    expect_matrix_near(mid.matrix() * mid.inverse_matrix(), Mat4(1.f), 1e-5f);  // the stored inverse
  }
}

// A scale of 1e-12 gives a determinant of 1e-36, below what a general inversion accepts; the
// interpolated transform's inverse comes from its factors.
TEST(AnimatedTransform, TinyScaleKeepsAnExactInverse) {
  AnimatedTransform a(scale(Vec3(1e-12f)), 0.f, translate(Vec3(1, 0, 0)) * scale(Vec3(2e-12f)), 1.f);
  Transform mid = a.interpolate(0.5f);
  EXPECT_NEAR(mid.matrix()[0][0], 1.5e-12f, 1e-17f);
  EXPECT_NEAR(mid.inverse_matrix()[0][0], 1.f / 1.5e-12f, 1e6f);
  EXPECT_NEAR(mid.inverse().point(Vec3(0.5f, 0, 0)).x, 0.f, 1e-3f);
}

TEST(AnimatedTransform, RefusesAMotionThatUnmirrors) {
  EXPECT_THROW(AnimatedTransform(scale(Vec3(1, 1, -1)), 0.f, Transform(), 1.f), std::domain_error);
  EXPECT_THROW(AnimatedTransform(Transform(), 0.f, perspective(60, 0.1f, 10.f), 1.f), std::domain_error);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
