// The biconic (toric) profile against outside answers: with equal meridians it is the conic of
// conic_surface.h (closed-form intersection) to 1e-12; its sag is the published biconic formula
// (evaluated here in long double in the rotated meridian frame); its slopes are that formula's
// derivatives (central differences here); a cylinder (one flat meridian) is hit where the
// quadratic of a circular cylinder says; rays beyond the rim or pointing away miss, no NaN.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/unity_id.h"
#include "optics/biconic_surface.h"
#include "optics/conic_surface.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// z = (c1 u^2 + c2 v^2) / (1 + sqrt(1 - (1+Q1) c1^2 u^2 - (1+Q2) c2^2 v^2)), u along the axis.
long double biconic_sag_ld(long double R1, long double Q1, long double R2, long double Q2, long double axis_deg,
                           long double x, long double y) {
  const long double a = axis_deg * std::numbers::pi_v<long double> / 180.0L;
  const long double u = std::cos(a) * x + std::sin(a) * y, v = -std::sin(a) * x + std::cos(a) * y;
  const long double c1 = 1.0L / R1, c2 = 1.0L / R2;
  return (c1 * u * u + c2 * v * v) /
         (1.0L + std::sqrt(1.0L - (1.0L + Q1) * c1 * c1 * u * u - (1.0L + Q2) * c2 * c2 * v * v));
}

TEST(BiconicSurface, EqualMeridiansMatchTheConicTo1e12) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  struct Case {
    double R, Q;
  };
  // Navarro's corneal and lens surfaces, a sphere, a paraboloid, an oblate ellipsoid.
  for (const Case c : {Case{7.72, -0.26}, Case{6.5, 0.0}, Case{10.2, -3.1316}, Case{-6.0, -1.0}, Case{12.0, 0.5}}) {
    const SurfaceProfile conic = SurfaceProfile::from_radius(c.R, c.Q);
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
      const double axis = 90.0 * (1.0 + u(rng));  // [0, 180)
      const SurfaceProfile bi = SurfaceProfile::biconic(1.0 / c.R, c.Q, 1.0 / c.R, c.Q, axis);
      const double h = 0.9 * std::fmin(conic.max_height(), 5.0);
      const glm::dvec3 o(h * u(rng), h * u(rng), -3.0 + u(rng));
      const glm::dvec3 d = glm::normalize(glm::dvec3(0.2 * u(rng), 0.2 * u(rng), 1.0));
      const ProfileHit a = intersect(conic, o, d), b = intersect(bi, o, d);
      ASSERT_EQ(a.hit, b.hit) << "R " << c.R << " ray " << k;
      if (!a.hit) continue;
      ++hits;
      EXPECT_NEAR(b.t, a.t, 1e-12) << "R " << c.R << " axis " << axis;
      const glm::dvec3 p = o + a.t * d;
      const glm::dvec3 na = normal(conic, p), nb = normal(bi, p);
      EXPECT_NEAR(glm::length(na - nb), 0.0, 1e-12);
      EXPECT_NEAR(bi.sag(p.x, p.y), conic.sag(p.x * p.x + p.y * p.y), 1e-12);
    }
    EXPECT_GT(hits, 1000);
  }
}

TEST(BiconicSurface, SagIsTheBiconicFormula) {
  // An astigmatic cornea: 7.72 / 7.50 mm, conics -0.26 / -0.15, first meridian at 30 deg.
  const double R1 = 7.72, Q1 = -0.26, R2 = 7.5, Q2 = -0.15, axis = 30.0;
  const SurfaceProfile s = SurfaceProfile::biconic(1.0 / R1, Q1, 1.0 / R2, Q2, axis);
  for (double x = -4.0; x <= 4.0; x += 0.25)
    for (double y = -4.0; y <= 4.0; y += 0.25)
      EXPECT_NEAR(s.sag(x, y), static_cast<double>(biconic_sag_ld(R1, Q1, R2, Q2, axis, x, y)), 1e-13)
          << x << ", " << y;
  // Along the principal meridians it is each meridian's conic.
  const double a = axis * std::numbers::pi / 180.0;
  for (double r = 0.0; r <= 4.0; r += 0.5) {
    EXPECT_NEAR(s.sag(r * std::cos(a), r * std::sin(a)), SurfaceProfile::from_radius(R1, Q1).sag(r * r), 1e-13);
    EXPECT_NEAR(s.sag(-r * std::sin(a), r * std::cos(a)), SurfaceProfile::from_radius(R2, Q2).sag(r * r), 1e-13);
  }
  // The reach is the smaller of the meridians': R / sqrt(1 + Q), 7.5 / sqrt(0.85) here.
  EXPECT_NEAR(s.max_height(), R2 / std::sqrt(1.0 + Q2), 1e-12);
}

TEST(BiconicSurface, HitsLieOnTheSheetAndNormalsAreTheFormulasGradient) {
  const double R1 = 7.72, Q1 = -0.26, R2 = 7.3, Q2 = 0.1, axis = 127.0;
  const SurfaceProfile s = SurfaceProfile::biconic(1.0 / R1, Q1, 1.0 / R2, Q2, axis);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int k = 0; k < 5000; ++k) {
    const glm::dvec3 o(4.0 * u(rng), 4.0 * u(rng), -2.0);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3 * u(rng), 0.3 * u(rng), 1.0));
    const ProfileHit h = intersect(s, o, d);
    ASSERT_FALSE(h.diverged);
    if (!h.hit) continue;
    ++hits;
    const glm::dvec3 p = o + h.t * d;
    EXPECT_NEAR(p.z, static_cast<double>(biconic_sag_ld(R1, Q1, R2, Q2, axis, p.x, p.y)), 1e-12);
    // Gradient of sag - z by central differences of the formula (step 1e-5 mm, long double).
    const long double e = 1e-5L;
    const long double gx =
        (biconic_sag_ld(R1, Q1, R2, Q2, axis, p.x + e, p.y) - biconic_sag_ld(R1, Q1, R2, Q2, axis, p.x - e, p.y)) /
        (2 * e);
    const long double gy =
        (biconic_sag_ld(R1, Q1, R2, Q2, axis, p.x, p.y + e) - biconic_sag_ld(R1, Q1, R2, Q2, axis, p.x, p.y - e)) /
        (2 * e);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(double(gx), double(gy), -1.0));
    EXPECT_NEAR(glm::length(normal(s, p) - expected), 0.0, 1e-9);
  }
  EXPECT_GT(hits, 4000);
}

TEST(BiconicSurface, CylinderMatchesTheCircularCylinder) {
  // First meridian (x, axis 0) curved with R = 10, second flat: x^2 + (z - R)^2 = R^2 near the
  // vertex. A ray o + t d: (dx^2 + dz^2) t^2 + 2 (ox dx + (oz - R) dz) t + ox^2 + (oz - R)^2 - R^2
  // = 0, the smaller root.
  const double R = 10.0;
  const SurfaceProfile s = SurfaceProfile::biconic(1.0 / R, 0.0, 0.0, 0.0, 0.0);
  const glm::dvec3 o(2.0, 7.0, -3.0);
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.15, -0.4, 1.0));
  const long double a = (long double)d.x * d.x + (long double)d.z * d.z;
  const long double b = (long double)o.x * d.x + ((long double)o.z - R) * d.z;
  const long double c = (long double)o.x * o.x + ((long double)o.z - R) * (o.z - R) - (long double)R * R;
  const long double t = (-b - std::sqrt(b * b - a * c)) / a;
  const ProfileHit hit = intersect(s, o, d);
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, static_cast<double>(t), 1e-12);
  // Turned to axis 90 the curved meridian is y: the same ray with x and y swapped.
  const SurfaceProfile turned = SurfaceProfile::biconic(1.0 / R, 0.0, 0.0, 0.0, 90.0);
  const ProfileHit swapped = intersect(turned, {o.y, o.x, o.z}, {d.y, d.x, d.z});
  ASSERT_TRUE(swapped.hit);
  EXPECT_NEAR(swapped.t, static_cast<double>(t), 1e-12);
}

// The first crossing, whichever way the intersection finds it (Newton from the start conic, the
// vertex plane, or the bracketed search): random strongly astigmatic biconics and rays from any
// side, against a brute-force search written here (the formula in long double sampled every
// 0.5 um along the ray, the first sign change inside the rim, bisected).
TEST(BiconicSurface, FirstCrossingMatchesABruteForceSearch) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hits = 0, misses = 0, differ = 0;
  for (int k = 0; k < 400; ++k) {
    const double R1 = (u(rng) < 0.5 ? -1 : 1) * (4.0 + 20.0 * u(rng)),
                 R2 = (u(rng) < 0.5 ? -1 : 1) * (4.0 + 20.0 * u(rng));
    const double Q1 = -1.5 + 2.0 * u(rng), Q2 = -1.5 + 2.0 * u(rng), axis = 180.0 * u(rng);
    const SurfaceProfile s = SurfaceProfile::biconic(1.0 / R1, Q1, 1.0 / R2, Q2, axis);
    const glm::dvec3 o(8.0 * (u(rng) - 0.5), 8.0 * (u(rng) - 0.5), -4.0 + 3.0 * u(rng));
    const double theta = 1.4 * u(rng), phi = 2.0 * std::numbers::pi * u(rng);  // up to 80 deg off the axis
    const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    auto g = [&](long double t, bool& valid) {
      const long double x = o.x + t * d.x, y = o.y + t * d.y, z = o.z + t * d.z;
      const long double a = axis * std::numbers::pi_v<long double> / 180.0L;
      const long double uu = std::cos(a) * x + std::sin(a) * y, vv = -std::sin(a) * x + std::cos(a) * y;
      const long double rad = 1.0L - (1.0L + Q1) * uu * uu / (R1 * R1) - (1.0L + Q2) * vv * vv / (R2 * R2);
      valid = rad > 0.0L;
      return valid ? z - (uu * uu / R1 + vv * vv / R2) / (1.0L + std::sqrt(rad)) : 0.0L;
    };
    long double t_ref = -1.0L;
    bool prev_valid = false;
    long double prev = 0.0L;
    for (int i = 0; i <= 60000; ++i) {  // t in [0, 30] mm
      const long double t = i * 0.0005L;
      bool valid = false;
      const long double now = g(t, valid);
      if (valid && prev_valid && (prev < 0.0L) != (now < 0.0L)) {
        long double lo = t - 0.0005L, hi = t;
        for (int it = 0; it < 80; ++it) {
          const long double mid = 0.5L * (lo + hi);
          bool v = false;
          ((g(mid, v) < 0.0L) == (prev < 0.0L) ? lo : hi) = mid;
        }
        t_ref = 0.5L * (lo + hi);
        break;
      }
      prev_valid = valid, prev = now;
    }
    const ProfileHit hit = intersect(s, o, d);
    EXPECT_FALSE(hit.diverged) << k;
    if (t_ref < 0.0L) {
      // No crossing within 30 mm (a hit further on, or a tangent touch, would be found by the
      // intersection but not here).
      if (hit.hit && hit.t < 30.0) ++differ;
      ++misses;
      continue;
    }
    ++hits;
    ASSERT_TRUE(hit.hit) << k;
    if (std::abs(hit.t - static_cast<double>(t_ref)) > 1e-9) ++differ;
    EXPECT_NEAR(hit.t, static_cast<double>(t_ref), 1e-9) << k << " R " << R1 << "/" << R2 << " Q " << Q1 << "/" << Q2;
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 20);
}

TEST(BiconicSurface, MissesBeyondTheRimAndBehindWithoutNaN) {
  const SurfaceProfile s = SurfaceProfile::biconic(1.0 / 7.72, -0.26, 1.0 / 7.0, 0.0, 0.0);
  // Parallel to the axis beyond the x meridian's reach (8.97 mm): no sheet there.
  const ProfileHit beyond = intersect(s, {9.5, 0.0, -5.0}, {0.0, 0.0, 1.0});
  EXPECT_FALSE(beyond.hit);
  EXPECT_FALSE(beyond.diverged);
  // Pointing away from the surface.
  const ProfileHit away = intersect(s, {0.5, 0.5, -5.0}, {0.0, 0.0, -1.0});
  EXPECT_FALSE(away.hit);
  // Parallel to the vertex plane, in front of it: never meets the sheet.
  const ProfileHit parallel = intersect(s, {0.0, 0.0, -1.0}, {1.0, 0.0, 0.0});
  EXPECT_FALSE(parallel.hit);
  // A ray starting on the vertex meets it at t = 0 (a stop on a lens vertex).
  const ProfileHit on = intersect(s, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
  ASSERT_TRUE(on.hit);
  EXPECT_NEAR(on.t, 0.0, 1e-15);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
