// Real-ray tracer: axial rays, symmetry, reciprocity, sub-ranges, failure statuses, agreement
// with paraxial optics in the small-aperture limit and with the thin-lens formula.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {

Prescription eye(const char* model, const char* variant = "") {
  EyeOptions o;
  o.model = model;
  o.variant = variant;
  return make_eye(o);
}

std::vector<Prescription> all_presets() {
  std::vector<Prescription> out;
  for (const std::string& m : eye_model_names()) out.push_back(eye(m.c_str()));
  out.push_back(eye("navarro", "wu2011"));
  return out;
}

Surface surface(const char* name, double radius, double thickness, double index, double sd,
                SurfaceRole role = SurfaceRole::Refract) {
  Surface s;
  s.name = name;
  s.profile = SurfaceProfile::from_radius(radius, 0.0);
  s.thickness_mm = thickness;
  s.index_after = index;
  s.medium = index == 1.0 ? "air" : "glass";
  s.semi_diameter_mm = sd;
  s.role = role;
  return s;
}

// Biconvex thin lens R1 = 50, R2 = -50, n = 1.5, 1 um thick: 20 D, f = 50 mm.
Prescription thin_lens() {
  Prescription p;
  p.name = "thin lens";
  p.surfaces = {surface("stop", 0, 0, 1.0, 5.0, SurfaceRole::Stop), surface("front", 50, 0.001, 1.5, 0.1),
                surface("back", -50, 50.0, 1.0, 0.1), surface("film", 0, 0, 1.0, 0, SurfaceRole::Image)};
  return p;
}

TEST(SequentialTrace, AxialRayPassesUndeviated) {
  for (const Prescription& p : all_presets()) {
    const CompiledSystem sys(p);
    const TraceResult f = sys.trace_forward({{0, 0, -10}, {0, 0, 1}});
    ASSERT_TRUE(f.ok()) << p.name << ": " << to_string(f.status);
    EXPECT_EQ(f.surface, sys.image_index());
    EXPECT_EQ(f.ray.origin.x, 0.0);
    EXPECT_EQ(f.ray.origin.y, 0.0);
    EXPECT_NEAR(f.ray.origin.z, p.axial_length_mm(), 1e-12) << p.name;
    EXPECT_EQ(f.ray.direction, glm::dvec3(0, 0, 1)) << p.name;
    const TraceResult r = sys.trace_reverse({{0, 0, p.axial_length_mm()}, {0, 0, -1}});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.surface, 0);
    EXPECT_EQ(r.ray.origin.x, 0.0);
    EXPECT_EQ(r.ray.origin.y, 0.0);
    EXPECT_NEAR(r.ray.origin.z, 0.0, 1e-12);
    EXPECT_EQ(r.ray.direction, glm::dvec3(0, 0, -1));
  }
}

TEST(SequentialTrace, RotatingTheRayRotatesTheResult) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Prescription& p : all_presets()) {
    const CompiledSystem sys(p);
    for (int k = 0; k < 50; ++k) {
      const Ray ray{{u(rng) * 1.5, u(rng) * 1.5, -2.0}, glm::normalize(glm::dvec3(u(rng) * 0.3, u(rng) * 0.3, 1.0))};
      const double phi = 3.0 * u(rng), c = std::cos(phi), s = std::sin(phi);
      auto rot = [c, s](glm::dvec3 v) { return glm::dvec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z); };
      const TraceResult a = sys.trace_forward(ray);
      const TraceResult b = sys.trace_forward({rot(ray.origin), rot(ray.direction)});
      ASSERT_EQ(a.status, b.status);
      ASSERT_EQ(a.surface, b.surface);
      if (!a.ok()) continue;
      EXPECT_LT(glm::length(rot(a.ray.origin) - b.ray.origin), 1e-12);
      EXPECT_LT(glm::length(rot(a.ray.direction) - b.ray.direction), 1e-12);
    }
  }
}

TEST(SequentialTrace, ReverseRetracesTheForwardPath) {
  // Reciprocity: from the retina point, back along the arriving direction, the ray leaves the
  // cornea where the forward ray entered, in the opposite direction.
  const Prescription p = eye("navarro");
  const CompiledSystem sys(p);
  glm::dvec3 points[8];
  for (double y : {0.3, 1.0, 1.7}) {
    const Ray in{{0.2, y, -3.0}, glm::normalize(glm::dvec3(0.01, 0.05, 1.0))};
    const TraceResult f = sys.trace_range(in, 0, sys.image_index(), points);
    ASSERT_TRUE(f.ok());
    const TraceResult r = sys.trace_reverse({f.ray.origin, -f.ray.direction});
    ASSERT_TRUE(r.ok());
    EXPECT_LT(glm::length(r.ray.origin - points[0]), 1e-10);
    EXPECT_LT(glm::length(r.ray.direction + in.direction), 1e-12);
  }
}

TEST(SequentialTrace, SubRangeStopsAtTheStopPlane) {
  const Prescription p = eye("navarro");
  const CompiledSystem sys(p);
  const Ray from_retina{{0.5, -1.0, p.axial_length_mm() - 0.01}, glm::normalize(glm::dvec3(0.0, 0.05, -1.0))};
  const TraceResult r = sys.trace_range(from_retina, sys.image_index() - 1, sys.stop_index());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.surface, sys.stop_index());
  EXPECT_NEAR(r.ray.origin.z, 3.6, 1e-12);
  // Continuing from the stop to the cornea gives the same as one full reverse trace.
  const TraceResult rest = sys.trace_range(r.ray, sys.stop_index() - 1, 0);
  const TraceResult full = sys.trace_reverse(from_retina);
  EXPECT_LT(glm::length(rest.ray.origin - full.ray.origin), 1e-12);
  EXPECT_LT(glm::length(rest.ray.direction - full.ray.direction), 1e-12);
}

// The batch trace (packed arithmetic, branch-free selects) must give the single-ray trace's
// bits for every ray, lost ones included: from the retina towards the pupil, at grazing angles
// and away from the system, in every preset, both directions, and in batches of odd sizes.
TEST(SequentialTrace, BatchEqualsSingleRaysBitForBit) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Prescription& p : all_presets()) {
    const CompiledSystem sys(p);
    const double length = p.axial_length_mm();
    std::vector<Ray> rays(997);
    for (size_t i = 0; i < rays.size(); ++i) {
      const glm::dvec3 at(u(rng) * 3, u(rng) * 3, length - 0.5 - std::abs(u(rng)));
      const double spread = i % 3 == 0 ? 2.0 : 0.4;  // a third aimed anywhere, some backwards
      rays[i] = {at, glm::dvec3(u(rng) * spread, u(rng) * spread, i % 7 == 0 ? u(rng) : -1.0)};
    }
    std::vector<TraceResult> results(rays.size());
    int statuses[5] = {};
    for (int first : {sys.image_index() - 1, sys.stop_index()}) {
      sys.trace_range_batch(rays.data(), results.data(), rays.size(), first, 0);
      for (size_t i = 0; i < rays.size(); ++i) {
        const TraceResult one = sys.trace_range(rays[i], first, 0);
        ++statuses[static_cast<int>(results[i].status)];
        ASSERT_EQ(one.status, results[i].status) << p.name << " ray " << i;
        ASSERT_EQ(one.surface, results[i].surface) << p.name << " ray " << i;
        ASSERT_EQ(one.ray.origin, results[i].ray.origin) << p.name << " ray " << i;
        ASSERT_EQ(one.ray.direction, results[i].ray.direction) << p.name << " ray " << i;
      }
    }
    // Forward, object space to the image.
    for (Ray& r : rays) r = {{u(rng) * 6, u(rng) * 6, -5.0}, {u(rng) * 0.3, u(rng) * 0.3, 1.0}};
    sys.trace_range_batch(rays.data(), results.data(), 13, 0, sys.image_index());
    for (size_t i = 0; i < 13; ++i) {
      const TraceResult one = sys.trace_forward(rays[i]);
      ASSERT_EQ(one.status, results[i].status);
      ASSERT_EQ(one.ray.origin, results[i].ray.origin);
      ASSERT_EQ(one.ray.direction, results[i].ray.direction);
    }
    // The mixture exercised passing and lost rays of several kinds.
    EXPECT_GT(statuses[static_cast<int>(TraceStatus::Ok)], 20) << p.name;
    EXPECT_GT(statuses[static_cast<int>(TraceStatus::StopBlocked)] + statuses[static_cast<int>(TraceStatus::Vignetted)],
              50)
        << p.name;
    EXPECT_GT(statuses[static_cast<int>(TraceStatus::Missed)], 0) << p.name;
  }
}

TEST(SequentialTrace, LostRaysReportKindAndSurface) {
  const Prescription p = eye("navarro");  // 4 mm pupil, lens rims 3.75 mm
  const CompiledSystem sys(p);
  // Through the cornea at 3 mm height, parallel: the iris (surface 2) blocks it.
  TraceResult r = sys.trace_forward({{0, 3.0, -1}, {0, 0, 1}});
  EXPECT_EQ(r.status, TraceStatus::StopBlocked);
  EXPECT_EQ(r.surface, 2);
  EXPECT_TRUE(std::isfinite(r.ray.origin.y));
  // Outside the cornea's 4.82 mm rim.
  r = sys.trace_forward({{0, 5.0, -1}, {0, 0, 1}});
  EXPECT_EQ(r.status, TraceStatus::Vignetted);
  EXPECT_EQ(r.surface, 0);
  EXPECT_EQ(r.ray.origin, glm::dvec3(0, 5.0, -1));  // the ray before the failing surface
  // Going away from the system.
  r = sys.trace_forward({{0, 0, -1}, {0, 0, -1}});
  EXPECT_EQ(r.status, TraceStatus::Missed);
  EXPECT_EQ(r.surface, 0);
}

TEST(SequentialTrace, TotalInternalReflectionIsDetected) {
  // Glass n = 1.5 behind a flat face: from inside at 60 deg (critical angle 41.8 deg) the
  // reverse ray cannot leave; at 30 deg it leaves with sin(theta') = 1.5 sin 30 deg.
  Prescription p;
  p.surfaces = {surface("face", 0, 5.0, 1.5, 0), surface("stop", 0, 5.0, 1.5, 50.0, SurfaceRole::Stop),
                surface("image", 0, 0, 1.5, 0, SurfaceRole::Image)};
  const CompiledSystem sys(p);
  const double a60 = 60.0 * std::numbers::pi / 180.0, a30 = 30.0 * std::numbers::pi / 180.0;
  TraceResult r = sys.trace_reverse({{0, 0, 10}, {0, std::sin(a60), -std::cos(a60)}});
  EXPECT_EQ(r.status, TraceStatus::TotalInternalReflection);
  EXPECT_EQ(r.surface, 0);
  r = sys.trace_reverse({{0, 0, 10}, {0, std::sin(a30), -std::cos(a30)}});
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.ray.direction.y, 0.75, 1e-14);
  EXPECT_NEAR(glm::length(r.ray.direction), 1.0, 1e-15);
}

TEST(SequentialTrace, ThinLensFocusesAtItsFocalLength) {
  // Lensmaker: P = (n-1)(1/R1 - 1/R2) = 20 D (+ a 1e-6 D thickness term): f = 50 mm.
  const Prescription p = thin_lens();
  const ParaxialData d = paraxial_analysis(p);
  EXPECT_NEAR(d.power_D, 20.0, 1e-4);
  EXPECT_NEAR(d.back_focal_distance_mm, 50.0, 1e-3);
  // Thin-lens imaging: an object 200 mm in front (vergence -5 D) images 1/(1/50 - 1/200) mm behind.
  EXPECT_NEAR(image_position_for_refraction(p, -5.0), 200.0 / 3.0, 2e-3);
  // A real ray at 0.01 mm height crosses the axis 50 mm behind the lens (aberrations ~1e-6 mm).
  const CompiledSystem sys(p);
  const TraceResult t = sys.trace_range({{0, 0.01, -1}, {0, 0, 1}}, 0, 2);
  ASSERT_TRUE(t.ok());
  const double z_cross = t.ray.origin.z - t.ray.origin.y / t.ray.direction.y * t.ray.direction.z;
  EXPECT_NEAR(z_cross, 50.0, 2e-3);
}

TEST(SequentialTrace, SmallRaysConvergeOnTheParaxialFocus) {
  for (const Prescription& p : all_presets()) {
    const ParaxialData d = paraxial_analysis(p);
    const CompiledSystem sys(p);
    const int last = sys.image_index() - 1;
    const TraceResult t = sys.trace_range({{0, 0.005, -1}, {0, 0, 1}}, 0, last);
    ASSERT_TRUE(t.ok());
    const double z_cross = t.ray.origin.z - t.ray.origin.y / t.ray.direction.y * t.ray.direction.z;
    EXPECT_NEAR(z_cross, d.back_focal_point_mm, 2e-4) << p.name;
  }
}

TEST(SequentialTrace, InvalidPrescriptionIsRejectedAtCompileTime) {
  Prescription p = thin_lens();
  p.surfaces[1].thickness_mm = -1.0;
  EXPECT_THROW(CompiledSystem{p}, OpticsError);
}

}  // namespace
}  // namespace eyetrace::optics
