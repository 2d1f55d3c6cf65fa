// Stress test of eyes with corrections (spectacle_lens.h, contact_lens.h, with the corneal
// cylinder and decentred iris they correct or live with): 10 million random reverse rays (retina
// -> world, as the eye camera traces) through 100 random Navarro and Le Grand eyes: refractive
// error -8..+6 D by length or cornea, corneal cylinder 0-3 D at a random axis, iris up to 0.5 mm
// off the axis, a contact lens (-8..+8 D) on a third of them, a spectacle lens (-8..+6 D sphere,
// 0..-3 D cylinder at a random axis, vertex distance 8-16 mm) on two thirds. Every result must be
// finite with a unit direction; every Ok ray must leave on the first surface's sheet (the
// spectacle's front, or the contact lens's) inside its clear aperture; lost rays must name a valid
// surface; lost rays are counted by kind and printed.
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/reverse_trace_stress.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

EyeOptions random_corrected_eye(int k, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  EyeOptions o;
  o.model = k % 2 ? "legrand" : "navarro";
  o.pupil_diameter_mm = 1.0 + 7.0 * u(rng);
  o.refractive_error_D = -8.0 + 14.0 * u(rng);
  o.ametropia = k % 4 < 2 ? Ametropia::Axial : Ametropia::Refractive;
  o.cylinder_D = -3.0 * u(rng), o.axis_deg = 180.0 * u(rng);
  o.pupil_decentration_x_mm = 0.5 * (2.0 * u(rng) - 1.0), o.pupil_decentration_y_mm = 0.5 * (2.0 * u(rng) - 1.0);
  if (k % 3 == 0) o.contact_lens_D = -8.0 + 16.0 * u(rng);
  if (k % 3 != 2) {
    SpectacleLens l;
    l.sphere_D = -8.0 + 14.0 * u(rng), l.cylinder_D = -3.0 * u(rng), l.axis_deg = 180.0 * u(rng);
    l.vertex_distance_mm = 8.0 + 8.0 * u(rng);
    o.spectacle = l;
  }
  return o;
}

TEST(CorrectedEyeTraceStress, TenMillionReverseRays) {
  constexpr int kEyes = 100, kRaysPerEye = 100000;
  std::mt19937_64 rng(20261126);
  std::array<long, 6> by_status{};
  long non_finite = 0, unit_failures = 0, off_surface = 0, bad_surface = 0;
  std::vector<Ray> rays(kRaysPerEye);
  std::vector<TraceResult> results(kRaysPerEye);
  auto finite = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (int k = 0; k < kEyes; ++k) {
    const EyeOptions o = random_corrected_eye(k, rng);
    const Prescription p = make_eye(o);
    const CompiledSystem sys(p);
    ASSERT_FALSE(sys.rotationally_symmetric());
    for (Ray& r : rays) r = test::random_reverse_ray(p, sys, o.pupil_diameter_mm, rng);
    sys.trace_reverse_batch(rays.data(), results.data(), rays.size());
    const Surface& first = p.surfaces[0];
    for (const TraceResult& t : results) {
      ++by_status[static_cast<int>(t.status)];
      if (!finite(t.ray.origin) || !finite(t.ray.direction)) ++non_finite;
      if (std::abs(glm::length(t.ray.direction) - 1.0) > 1e-12) ++unit_failures;
      if (t.ok()) {
        const glm::dvec3& q = t.ray.origin;
        const double r2 = q.x * q.x + q.y * q.y;
        if (t.surface != 0 || r2 > first.semi_diameter_mm * first.semi_diameter_mm * (1 + 1e-12) ||
            std::abs(q.z - first.profile.sag(q.x, q.y)) > 1e-9)
          ++off_surface;
      } else if (t.surface < 0 || t.surface > sys.image_index() - 1) {
        ++bad_surface;
      }
    }
  }
  const long total = long(kEyes) * kRaysPerEye;
  std::printf("%ld rays: ok %ld, missed %ld, vignetted %ld, stop %ld, TIR %ld, no convergence %ld\n", total,
              by_status[0], by_status[1], by_status[2], by_status[3], by_status[4], by_status[5]);
  EXPECT_EQ(non_finite, 0);
  EXPECT_EQ(unit_failures, 0);
  EXPECT_EQ(off_surface, 0);
  EXPECT_EQ(bad_surface, 0);
  EXPECT_GT(by_status[0], total / 4);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
