// Stress test of the per-ray-wavelength trace, the spectral eye camera's hot path: 10 million
// random reverse rays (retina -> world), each at its own random wavelength in 360-830 nm, through
// every preset with random accommodation, pupils 0.5-9 mm, refractive errors, retina shapes and
// compiled wavelengths, retina points out to 90 deg. Batched and single-ray traces alternate by
// configuration (the batches on both instruction sets where the CPU has AVX2), and a sample of
// the batched rays is retraced one by one. Every result must be
// finite, every direction unit length, every Ok ray must really leave through the cornea's clear
// aperture, every lost ray must carry a failure status and a valid surface, and the sampled
// batched rays must equal their single-ray traces bit for bit.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/reverse_trace_stress.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(WavelengthTraceStress, TenMillionRandomRaysAtRandomWavelengthsAreFiniteAndAccounted) {
  constexpr int kConfigs = 210;
  constexpr int kRaysPerConfig = 48000;  // 10.08 million rays
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  test::StressTally tally;
  long batch_differs = 0, sampled = 0;
  std::vector<Ray> rays(kRaysPerConfig);
  std::vector<double> lambda(kRaysPerConfig);
  std::vector<TraceResult> results(kRaysPerConfig);
  const auto start = std::chrono::steady_clock::now();
  const TraceBatchIsa start_isa = trace_batch_isa();

  for (int k = 0; k < kConfigs; ++k) {
    const EyeOptions o = test::random_stress_eye(k, rng);
    const Prescription p = make_eye(o);
    const CompiledSystem sys(p);
    for (size_t j = 0; j < rays.size(); ++j) {
      rays[j] = test::random_reverse_ray(p, sys, o.pupil_diameter_mm, rng);
      lambda[j] = 360.0 + 470.0 * u(rng);
    }
    const int first = sys.image_index() - 1;
    // Every other batched configuration on the baseline instruction set (SSE2), the rest on the
    // start-up choice (AVX2 where the CPU has it).
    set_trace_batch_isa(k % 4 == 0 ? TraceBatchIsa::Baseline : start_isa);
    if (k % 2 == 0) {
      sys.trace_range_batch(rays.data(), lambda.data(), results.data(), rays.size(), first, 0);
      for (size_t j = k % 97; j < rays.size(); j += 97) {  // about 1% retraced one by one
        const TraceResult one = sys.trace_range(rays[j], first, 0, lambda[j]);
        ++sampled;
        batch_differs += one.status != results[j].status || one.surface != results[j].surface ||
                         one.ray.origin != results[j].ray.origin || one.ray.direction != results[j].ray.direction;
      }
    } else {
      for (size_t j = 0; j < rays.size(); ++j) results[j] = sys.trace_range(rays[j], first, 0, lambda[j]);
    }
    for (const TraceResult& t : results) tally.add(t, p, sys);
  }
  set_trace_batch_isa(start_isa);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long total = static_cast<long>(kConfigs) * kRaysPerConfig;
  const auto& n = tally.by_status;
  std::printf(
      "%ld rays at random wavelengths in %.2f s (%.2f M/s incl. setup and checks, batch on baseline and %s): ok %ld, "
      "missed %ld, vignetted %ld, stop %ld, TIR %ld; %ld batched rays retraced singly\n",
      total, seconds, total / seconds / 1e6, to_string(trace_batch_isa()), n[0], n[1], n[2], n[3], n[4], sampled);
  tally.expect_clean(total, 10'000'000);
  EXPECT_EQ(batch_differs, 0);
  EXPECT_GT(sampled, 50'000);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
