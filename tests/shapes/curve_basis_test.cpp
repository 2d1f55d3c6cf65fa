// Curve bases (shapes/curve_basis.h): the Bezier segments made from B-spline and quadratic
// control points trace the same curve as the uniform B-spline / quadratic Bernstein polynomials
// evaluated directly (their textbook matrix forms, independent of the blossoming used), segment
// counts as pbrt-v4 defines them, and the Bezier derivative against a central difference.
#include "shapes/curve_basis.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::vector<Vec3> random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> x(-2.f, 2.f);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(Vec3(x(rng), x(rng), x(rng)));
  return p;
}

// Uniform cubic B-spline span (p0..p3) at t: (1/6) [(1-t)^3, 3t^3-6t^2+4, -3t^3+3t^2+3t+1, t^3].
Vec3 cubic_bspline(const Vec3* p, double t) {
  const double b0 = (1 - t) * (1 - t) * (1 - t), b1 = 3 * t * t * t - 6 * t * t + 4,
               b2 = -3 * t * t * t + 3 * t * t + 3 * t + 1, b3 = t * t * t;
  return Vec3((b0 * glm::dvec3(p[0]) + b1 * glm::dvec3(p[1]) + b2 * glm::dvec3(p[2]) + b3 * glm::dvec3(p[3])) / 6.0);
}

// Uniform quadratic B-spline span at t: (1/2) [(1-t)^2, -2t^2+2t+1, t^2].
Vec3 quadratic_bspline(const Vec3* p, double t) {
  const double b0 = (1 - t) * (1 - t), b1 = -2 * t * t + 2 * t + 1, b2 = t * t;
  return Vec3((b0 * glm::dvec3(p[0]) + b1 * glm::dvec3(p[1]) + b2 * glm::dvec3(p[2])) / 2.0);
}

// Quadratic Bernstein form.
Vec3 quadratic_bezier(const Vec3* p, double t) {
  return Vec3((1 - t) * (1 - t) * glm::dvec3(p[0]) + 2 * t * (1 - t) * glm::dvec3(p[1]) + t * t * glm::dvec3(p[2]));
}

void expect_near(const Vec3& a, const Vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(CurveBasis, SegmentCountsAsPbrtV4) {
  EXPECT_EQ(curve_segment_count(4, CurveBasis::Bezier, 3), 1);
  EXPECT_EQ(curve_segment_count(7, CurveBasis::Bezier, 3), 2);
  EXPECT_FALSE(curve_segment_count(5, CurveBasis::Bezier, 3));
  EXPECT_FALSE(curve_segment_count(3, CurveBasis::Bezier, 3));
  EXPECT_EQ(curve_segment_count(5, CurveBasis::Bezier, 2), 2);
  EXPECT_FALSE(curve_segment_count(4, CurveBasis::Bezier, 2));
  EXPECT_EQ(curve_segment_count(4, CurveBasis::BSpline, 3), 1);
  EXPECT_EQ(curve_segment_count(9, CurveBasis::BSpline, 3), 6);
  EXPECT_FALSE(curve_segment_count(3, CurveBasis::BSpline, 3));
  EXPECT_EQ(curve_segment_count(3, CurveBasis::BSpline, 2), 1);
  EXPECT_FALSE(curve_segment_count(4, CurveBasis::Bezier, 4));
  EXPECT_FALSE(curve_segment_count(0, CurveBasis::BSpline, 2));
}

TEST(CurveBasis, CubicBSplineSegmentsTraceTheBSpline) {
  const std::vector<Vec3> p = random_points(9, 1);
  const auto segs = cubic_bezier_segments(p, CurveBasis::BSpline, 3);
  ASSERT_EQ(segs.size(), 6u);
  for (size_t s = 0; s < segs.size(); ++s)
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.83, 1.0})
      expect_near(bezier_point(segs[s], float(t)), cubic_bspline(&p[s], t), 2e-6f);
}

TEST(CurveBasis, QuadraticBSplineSegmentsTraceTheBSpline) {
  const std::vector<Vec3> p = random_points(7, 2);
  const auto segs = cubic_bezier_segments(p, CurveBasis::BSpline, 2);
  ASSERT_EQ(segs.size(), 5u);
  for (size_t s = 0; s < segs.size(); ++s)
    for (double t : {0.0, 0.2, 0.5, 0.71, 1.0})
      expect_near(bezier_point(segs[s], float(t)), quadratic_bspline(&p[s], t), 2e-6f);
}

TEST(CurveBasis, QuadraticBezierIsElevatedWithoutChangingTheCurve) {
  const std::vector<Vec3> p = random_points(5, 3);
  const auto segs = cubic_bezier_segments(p, CurveBasis::Bezier, 2);
  ASSERT_EQ(segs.size(), 2u);
  for (size_t s = 0; s < 2; ++s)
    for (double t : {0.0, 0.3, 0.5, 0.9, 1.0})
      expect_near(bezier_point(segs[s], float(t)), quadratic_bezier(&p[2 * s], t), 2e-6f);
}

TEST(CurveBasis, CubicBezierSegmentsShareEndPointsAndDerivativeMatchesDifferences) {
  const std::vector<Vec3> p = random_points(10, 4);
  const auto segs = cubic_bezier_segments(p, CurveBasis::Bezier, 3);
  ASSERT_EQ(segs.size(), 3u);
  for (size_t s = 0; s < 3; ++s) {
    expect_near(bezier_point(segs[s], 0.f), p[3 * s], 0.f);
    expect_near(bezier_point(segs[s], 1.f), p[3 * s + 3], 1e-6f);
    // dP/du at the ends is 3 (p1 - p0) and 3 (p3 - p2); inside, a central difference.
    expect_near(bezier_derivative(segs[s], 0.f), 3.f * (p[3 * s + 1] - p[3 * s]), 1e-5f);
    expect_near(bezier_derivative(segs[s], 1.f), 3.f * (p[3 * s + 3] - p[3 * s + 2]), 1e-5f);
    const double h = 1e-3, t = 0.4;
    const Vec3 diff = Vec3(
        (glm::dvec3(bezier_point(segs[s], float(t + h))) - glm::dvec3(bezier_point(segs[s], float(t - h)))) / (2 * h));
    expect_near(bezier_derivative(segs[s], float(t)), diff, 2e-3f);
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
