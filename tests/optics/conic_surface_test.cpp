// Ray-conic intersection against closed-form answers (sphere, paraboloid, hyperboloid vertex
// sheet, prolate and oblate ellipsoids, plane), including grazing and missing rays.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/unity_id.h"
#include "optics/conic_surface.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// Closed-form sag of the vertex sheet: z = c r^2 / (1 + sqrt(1 - (1+Q) c^2 r^2)), long double.
long double sag_ld(long double R, long double Q, long double r) {
  const long double c = 1.0L / R;
  return c * r * r / (1.0L + std::sqrt(1.0L - (1.0L + Q) * c * c * r * r));
}

// A ray parallel to the axis at height h from z = z0 meets the vertex sheet at t = sag - z0.
void expect_parallel_hit(double R, double Q, double h) {
  const SurfaceProfile s = SurfaceProfile::from_radius(R, Q);
  const ProfileHit hit = intersect(s, {0.0, h, -5.0}, {0.0, 0.0, 1.0});
  ASSERT_TRUE(hit.hit) << "R " << R << " Q " << Q << " h " << h;
  EXPECT_NEAR(hit.t, static_cast<double>(sag_ld(R, Q, h) + 5.0L), 1e-12);
}

TEST(ConicIntersection, SphereParallelRayMatchesClosedForm) {
  // Sphere R = 10, h = 6: z = 10 - sqrt(100 - 36) = 2.
  const ProfileHit hit = intersect(SurfaceProfile::from_radius(10.0, 0.0), {0, 6, -5}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 7.0, 1e-13);
  expect_parallel_hit(-7.0, 0.0, 3.0);
}

TEST(ConicIntersection, SphereNormalPointsFromCentre) {
  const SurfaceProfile s = SurfaceProfile::from_radius(10.0, 0.0);
  const glm::dvec3 n = normal(s, {0.0, 6.0, 2.0});
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_NEAR(n.y, 0.6, 1e-15);  // (p - centre) / R with the centre at z = 10
  EXPECT_NEAR(n.z, -0.8, 1e-15);
  const glm::dvec3 v = normal(s, {0.0, 0.0, 0.0});
  EXPECT_EQ(v, glm::dvec3(0.0, 0.0, -1.0));
}

TEST(ConicIntersection, SphereGrazingRayHitsTheEquator) {
  // h = R: the discriminant is exactly 0; the touching point z = R is the rim of the vertex half.
  const ProfileHit hit = intersect(SurfaceProfile::from_radius(10.0, 0.0), {0, 10, -5}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 15.0, 1e-12);
}

TEST(ConicIntersection, SphereMissingRaysReportNoHit) {
  const SurfaceProfile s = SurfaceProfile::from_radius(10.0, 0.0);
  EXPECT_FALSE(intersect(s, {0, 10.001, -5}, {0, 0, 1}).hit);  // passes beside
  EXPECT_FALSE(intersect(s, {0, 0, -5}, {0, 0, -1}).hit);      // points away
  // Starting inside, behind the vertex: the front cap is behind the ray and the far half is
  // not the surface.
  EXPECT_FALSE(intersect(s, {0, 0, 5}, {0, 0, 1}).hit);
}

TEST(ConicIntersection, ParaboloidRayParallelToAxisUsesLinearCase) {
  // Q = -1: the quadratic coefficient vanishes for d = (0, 0, 1); z = r^2 / (2R).
  const ProfileHit hit = intersect(SurfaceProfile::from_radius(10.0, -1.0), {0, 4, -5}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 5.0 + 16.0 / 20.0, 1e-13);
  expect_parallel_hit(-6.0, -1.0, 3.75);
}

TEST(ConicIntersection, ParaboloidObliqueRayMatchesQuadratic) {
  // Ray (0, 0, -1) + t (0, s, c): (t s)^2 / 20 = -1 + t c, smaller positive root.
  const double a = 0.3, s = std::sin(a), c = std::cos(a);
  const long double A = s * s / 20.0L, B = -c, C = 1.0L;
  const long double t = (-B - std::sqrt(B * B - 4 * A * C)) / (2 * A);
  const ProfileHit hit = intersect(SurfaceProfile::from_radius(10.0, -1.0), {0, 0, -1}, {0, s, c});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, static_cast<double>(t), 1e-12);
}

TEST(ConicIntersection, HyperboloidTakesTheVertexSheet) {
  // Q = -3, R = 5: the far sheet crosses the axis at z = 2/((1+Q) c) = -5, in front of the
  // vertex. An axial ray from z = -100 meets it first (t = 95) but must hit the vertex (t = 100).
  const SurfaceProfile s = SurfaceProfile::from_radius(5.0, -3.0);
  const ProfileHit hit = intersect(s, {0, 0, -100}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 100.0, 1e-12);
  expect_parallel_hit(5.0, -3.0, 3.0);
  expect_parallel_hit(10.2, -3.1316, 3.75);  // Navarro's anterior lens
  EXPECT_TRUE(std::isinf(s.max_height()));
}

TEST(ConicIntersection, OblateEllipsoidHitAndReach) {
  // Q = +0.5: closed surface, reach 1/(|c| sqrt(1+Q)) = 10/sqrt(1.5).
  const SurfaceProfile s = SurfaceProfile::from_radius(10.0, 0.5);
  EXPECT_NEAR(s.max_height(), 10.0 / std::sqrt(1.5), 1e-12);
  expect_parallel_hit(10.0, 0.5, 5.0);
  expect_parallel_hit(10.0, 0.5, 8.0);
  EXPECT_FALSE(intersect(s, {0, 8.2, -5}, {0, 0, 1}).hit);  // beyond the reach: misses
  // From inside the far half, going on: the far half is rejected.
  EXPECT_FALSE(intersect(s, {0, 0, 2}, {0, 0, 1}).hit);
}

TEST(ConicIntersection, ProlateEllipsoid) {
  expect_parallel_hit(7.72, -0.26, 4.82);  // Navarro's anterior cornea
  expect_parallel_hit(-8.0, -0.5, 6.0);
}

TEST(ConicIntersection, PlaneHitAndParallelMiss) {
  const SurfaceProfile s = SurfaceProfile::plane();
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.1, 0.2, 1.0));
  const ProfileHit hit = intersect(s, {1, 2, -3}, d);
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 3.0 / d.z, 1e-13);
  EXPECT_FALSE(intersect(s, {1, 2, -3}, {1, 0, 0}).hit);
  EXPECT_EQ(normal(s, {3, 4, 0}), glm::dvec3(0, 0, -1));
}

TEST(ConicIntersection, NearlyFlatSurfaceKeepsPrecision) {
  // c = 1e-12 /mm: the sag at r = 1 is 5e-13 mm. The textbook root would lose it entirely.
  const SurfaceProfile s = SurfaceProfile::from_curvature(1e-12, 0.0);
  const ProfileHit hit = intersect(s, {0, 1, -5}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(-5.0 + hit.t, 5e-13, 2e-15);
}

TEST(ConicIntersection, RayStartingOnTheSurfaceMeetsItAtZero) {
  // A stop on a lens vertex: the ray starts on the vertex and must meet it at t = 0.
  const ProfileHit hit = intersect(SurfaceProfile::from_radius(10.0, 0.0), {0, 0, 0}, {0, 0, 1});
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 0.0, 1e-15);
}

TEST(ConicSag, MatchesClosedFormAndIsStableNearFlat) {
  EXPECT_NEAR(SurfaceProfile::from_radius(10.0, 0.0).sag(36.0), 2.0, 1e-14);
  EXPECT_NEAR(SurfaceProfile::from_radius(-6.0, -1.0).sag(9.0), -9.0 / 12.0, 1e-14);
  EXPECT_NEAR(SurfaceProfile::from_curvature(1e-15, 0.0).sag(4.0), 2e-15, 1e-28);
  EXPECT_EQ(SurfaceProfile::plane().sag(100.0), 0.0);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
