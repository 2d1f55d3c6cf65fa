// Stress test of phase plates in the trace (optics/phase_plate.h): 1 million random rays through
// Navarro eyes carrying a random measured wavefront to the 4th order (coefficients up to +-2 um
// each, up to 20 D of defocus and cylinder over the smallest pupils), measured over a random 2-8
// mm pupil, iris 1-8 mm: half reverse (retina -> world, as the eye camera traces), half forward,
// a quarter of all at a random per-ray wavelength. Every result must be finite with a unit
// direction and name a valid surface when lost; lost rays are counted by kind and printed. The
// wave report of each eye (OPD, fit, refraction) must be finite too.
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/reverse_trace_stress.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/phase_plate.h"
#include "optics/sequential_trace.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription random_measured_eye(std::mt19937_64& rng, double& iris_mm) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  EyeOptions o;
  o.model = "navarro";
  o.pupil_diameter_mm = iris_mm = 1.0 + 7.0 * u(rng);
  Prescription p = make_eye(o);
  ZernikeFile f;
  f.origin = "random.zer";
  f.pupil_diameter_mm = 2.0 + 6.0 * u(rng);
  f.max_order = 4;
  f.coefficients_um.resize(15);
  for (double& c : f.coefficients_um) c = 2.0 * (2.0 * u(rng) - 1.0);
  add_phase_plate(p, f);
  return p;
}

// From 5 mm in front of the cornea towards a point near the pupil, within 60 deg of the axis.
Ray random_forward_ray(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double theta = 60.0 * std::numbers::pi / 180.0 * std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
  const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  const glm::dvec3 target(8.0 * (u(rng) - 0.5), 8.0 * (u(rng) - 0.5), 3.6);
  return {target - (3.6 + 5.0) / d.z * d, d};
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(PhasePlateStress, MillionRandomRaysNoNaN) {
  constexpr int kEyes = 20, kRaysPerEye = 50000;
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::array<long, 6> by_status{};
  long non_finite = 0, unit_failures = 0, bad_surface = 0, total = 0;
  for (int k = 0; k < kEyes; ++k) {
    double iris_mm = 0.0;
    const Prescription p = random_measured_eye(rng, iris_mm);
    const CompiledSystem sys(p);
    ASSERT_FALSE(sys.rotationally_symmetric());
    for (int i = 0; i < kRaysPerEye; ++i) {
      const bool reverse = i % 2 == 0;
      const Ray ray = reverse ? test::random_reverse_ray(p, sys, iris_mm, rng) : random_forward_ray(rng);
      const int first = reverse ? sys.image_index() - 1 : 0, last = reverse ? 0 : sys.image_index();
      const TraceResult t =
          i % 4 < 2 ? sys.trace_range(ray, first, last) : sys.trace_range(ray, first, last, 380.0 + 400.0 * u(rng));
      ++by_status[static_cast<int>(t.status)], ++total;
      if (!finite(t.ray.origin) || !finite(t.ray.direction)) ++non_finite;
      if (std::abs(glm::length(t.ray.direction) - 1.0) > 1e-12) ++unit_failures;
      if (!t.ok() && (t.surface < 0 || t.surface > sys.image_index())) ++bad_surface;
    }
    const WavefrontResult w = trace_wavefront(p, WavefrontOptions{});
    EXPECT_TRUE(std::isfinite(w.rms_waves) && std::isfinite(w.pv_waves) && std::isfinite(w.least_squares.M_D) &&
                std::isfinite(w.paraxial.J0_D))
        << "eye " << k;
    for (double c : w.zernike_um) EXPECT_TRUE(std::isfinite(c)) << "eye " << k;
  }
  std::printf("%ld rays: ok %ld, missed %ld, vignetted %ld, stop %ld, TIR %ld, no convergence %ld\n", total,
              by_status[0], by_status[1], by_status[2], by_status[3], by_status[4], by_status[5]);
  EXPECT_EQ(total, 1'000'000);
  EXPECT_EQ(non_finite, 0);
  EXPECT_EQ(unit_failures, 0);
  EXPECT_EQ(bad_surface, 0);
  EXPECT_GT(by_status[0], total / 10);  // the eyes still image
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
