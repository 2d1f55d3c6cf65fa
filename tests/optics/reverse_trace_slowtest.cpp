// Stress test of the camera's hot path: 10 million random reverse rays (retina -> world)
// through every preset with random accommodation (0 to each model's maximum, 15 D for navarro),
// pupils 0.5-9 mm, refractive errors, wavelengths, and retina points out to 90 deg. Every result
// must be finite, every direction unit length, every Ok ray must really leave through the
// cornea's clear aperture, and every lost ray must carry a failure status and a valid surface.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
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

TEST(ReverseTraceStress, TenMillionRandomRaysAreFiniteAndAccounted) {
  constexpr int kConfigs = 210;
  constexpr int kRaysPerConfig = 48000;  // 10.08 million rays
  std::mt19937_64 rng(20240611);
  test::StressTally tally;
  std::vector<Ray> rays(kRaysPerConfig);
  std::vector<TraceResult> results(kRaysPerConfig);
  const auto start = std::chrono::steady_clock::now();

  for (int k = 0; k < kConfigs; ++k) {
    const EyeOptions o = test::random_stress_eye(k, rng);
    const Prescription p = make_eye(o);
    const CompiledSystem sys(p);
    for (Ray& r : rays) r = test::random_reverse_ray(p, sys, o.pupil_diameter_mm, rng);
    if (k % 2 == 0) {
      sys.trace_reverse_batch(rays.data(), results.data(), rays.size());
    } else {
      for (size_t j = 0; j < rays.size(); ++j) results[j] = sys.trace_reverse(rays[j]);
    }
    for (const TraceResult& t : results) tally.add(t, p, sys);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long total = static_cast<long>(kConfigs) * kRaysPerConfig;
  const auto& n = tally.by_status;
  std::printf(
      "%ld rays in %.2f s (%.2f M/s incl. setup and checks): ok %ld, missed %ld, vignetted %ld, "
      "stop %ld, TIR %ld\n",
      total, seconds, total / seconds / 1e6, n[0], n[1], n[2], n[3], n[4]);
  tally.expect_clean(total, 10'000'000);
}

// Throughput of the camera's hot path for the Navarro eye (4 mm pupil, retina points within
// 35 deg, rays aimed into the pupil), one thread, in process CPU time (best of 3) so that other
// load on a shared machine distorts it less. Printed, not asserted. The renderer needs
// >= 5 million reverse traces per second per core.
TEST(ReverseTraceStress, NavarroReverseTraceRate) {
  EyeOptions o;
  o.model = "navarro";
  const Prescription p = make_eye(o);
  const CompiledSystem sys(p);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Ray> rays(4096);
  const double length = p.axial_length_mm();
  for (Ray& r : rays) {
    const double a = 0.6 * u(rng), phi = 2.0 * std::numbers::pi * u(rng);
    const glm::dvec3 at = glm::dvec3(0, 0, length - 12.0) +
                          12.0 * glm::dvec3(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), std::cos(a));
    const double rt = 2.0 * std::sqrt(u(rng)), pt = 2.0 * std::numbers::pi * u(rng);
    r = {at, glm::normalize(glm::dvec3(rt * std::cos(pt), rt * std::sin(pt), 3.6) - at)};
  }
  std::vector<TraceResult> results(rays.size());
  constexpr int kRepeats = 500;  // 2 million rays per measurement
  double checksum = 0.0;
  auto time = [&](auto&& body) {
    double best = 1e300;
    for (int trial = 0; trial < 3; ++trial) {
      const std::clock_t start = std::clock();
      for (int k = 0; k < kRepeats; ++k) body();
      best = std::min(best, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
    }
    return best;
  };
  const double single = time([&] {
    for (const Ray& r : rays) checksum += sys.trace_reverse(r).ray.direction.z;
  });
  const double batch = time([&] {
    sys.trace_reverse_batch(rays.data(), results.data(), rays.size());
    checksum += results[0].ray.direction.z;
  });
  const double n = static_cast<double>(rays.size()) * kRepeats;
  std::printf("navarro reverse traces, one thread: %.2f M/s single, %.2f M/s batch (checksum %g)\n", n / single / 1e6,
              n / batch / 1e6, checksum);
  EXPECT_TRUE(std::isfinite(checksum));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
