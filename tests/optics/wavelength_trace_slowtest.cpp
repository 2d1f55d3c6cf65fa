// Stress test of the per-ray-wavelength trace, the spectral eye camera's hot path: 10 million
// random reverse rays (retina -> world), each at its own random wavelength in 360-830 nm, through
// every preset with random accommodation, pupils 0.5-9 mm, refractive errors, retina shapes and
// compiled wavelengths, retina points out to 90 deg. Batched and single-ray traces alternate by
// configuration (the batches on both instruction sets where the CPU has AVX2), and a sample of
// the batched rays is retraced one by one. Every result must be
// finite, every direction unit length, every Ok ray must really leave through the cornea's clear
// aperture, every lost ray must carry a failure status and a valid surface, and the sampled
// batched rays must equal their single-ray traces bit for bit.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "optics/eye_models.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(WavelengthTraceStress, TenMillionRandomRaysAtRandomWavelengthsAreFiniteAndAccounted) {
  struct Preset {
    const char* model;
    const char* variant;
  };
  const Preset presets[] = {{"navarro", ""},  {"navarro", "wu2011"}, {"gullstrand", ""}, {"legrand", ""},
                            {"kooijman", ""}, {"escudero-sanz", ""}, {"arizona", ""}};
  constexpr int kConfigs = 210;
  constexpr int kRaysPerConfig = 48000;  // 10.08 million rays
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::array<long, 5> by_status{};
  long unit_failures = 0, aperture_failures = 0, non_finite = 0, bad_surface = 0, batch_differs = 0, sampled = 0;
  std::vector<Ray> rays(kRaysPerConfig);
  std::vector<double> lambda(kRaysPerConfig);
  std::vector<TraceResult> results(kRaysPerConfig);
  const auto start = std::chrono::steady_clock::now();
  const TraceBatchIsa start_isa = trace_batch_isa();

  for (int k = 0; k < kConfigs; ++k) {
    const Preset& preset = presets[k % 7];
    EyeOptions o;
    o.model = preset.model;
    o.variant = preset.variant;
    o.accommodation_D = u(rng) * max_accommodation_D(o.model, o.variant);
    o.pupil_diameter_mm = 0.5 + 8.5 * u(rng);
    if (k % 3 == 0) o.refractive_error_D = -8.0 + 14.0 * u(rng);
    if (k % 4 == 0) o.wavelength_nm = 400.0 + 300.0 * u(rng);
    if (k % 5 == 0) o.retina_radius_mm = -(10.0 + 5.0 * u(rng));
    const Prescription p = make_eye(o);
    const CompiledSystem sys(p);
    const Surface& retina = p.surfaces.back();
    const double length = p.axial_length_mm();
    const double z_stop = sys.vertex_z(sys.stop_index());
    const Surface& cornea = p.surfaces.front();

    for (size_t j = 0; j < rays.size(); ++j) {
      const double phi = 2.0 * std::numbers::pi * u(rng);
      glm::dvec3 at;
      if (retina.profile.is_flat()) {
        const double rho = 14.0 * std::sqrt(u(rng));
        at = {rho * std::cos(phi), rho * std::sin(phi), length};
      } else {
        // Up to 90 deg from the axis, seen from the retina's centre of curvature.
        const double R = 1.0 / retina.profile.curvature;  // negative
        const double a = 0.5 * std::numbers::pi * u(rng);
        at = glm::dvec3(0, 0, length + R) -
             R * glm::dvec3(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), std::cos(a));
      }
      glm::dvec3 target;
      if (u(rng) < 0.9) {  // towards the pupil region (a bit beyond the iris)
        const double rt = 0.6 * o.pupil_diameter_mm * std::sqrt(u(rng)), pt = 2.0 * std::numbers::pi * u(rng);
        target = {rt * std::cos(pt), rt * std::sin(pt), z_stop + (u(rng) - 0.5)};
      } else {  // anywhere in front
        target = {20.0 * (u(rng) - 0.5), 20.0 * (u(rng) - 0.5), length - 30.0 * u(rng)};
      }
      rays[j] = {at, glm::normalize(target - at)};
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
    const double cornea_sd2 = cornea.semi_diameter_mm * cornea.semi_diameter_mm;
    for (const TraceResult& t : results) {
      ++by_status[static_cast<int>(t.status)];
      if (!finite(t.ray.origin) || !finite(t.ray.direction)) ++non_finite;
      if (std::abs(glm::length(t.ray.direction) - 1.0) > 1e-12) ++unit_failures;
      if (t.ok()) {
        // Really on the cornea, inside its clear aperture.
        const double r2 = t.ray.origin.x * t.ray.origin.x + t.ray.origin.y * t.ray.origin.y;
        if (t.surface != 0 || r2 > cornea_sd2 * (1 + 1e-12) || std::abs(t.ray.origin.z - cornea.profile.sag(r2)) > 1e-9)
          ++aperture_failures;
      } else if (t.surface < 0 || t.surface > sys.image_index() - 1) {
        ++bad_surface;
      }
    }
  }
  set_trace_batch_isa(start_isa);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long total = static_cast<long>(kConfigs) * kRaysPerConfig;
  std::printf(
      "%ld rays at random wavelengths in %.2f s (%.2f M/s incl. setup and checks, batch on baseline and %s): ok %ld, "
      "missed %ld, vignetted %ld, stop %ld, TIR %ld; %ld batched rays retraced singly\n",
      total, seconds, total / seconds / 1e6, to_string(trace_batch_isa()), by_status[0], by_status[1], by_status[2],
      by_status[3], by_status[4], sampled);
  EXPECT_GE(total, 10'000'000);
  EXPECT_EQ(non_finite, 0);
  EXPECT_EQ(unit_failures, 0);
  EXPECT_EQ(aperture_failures, 0);
  EXPECT_EQ(bad_surface, 0);
  EXPECT_EQ(batch_differs, 0);
  EXPECT_GT(sampled, 50'000);
  for (int s = 0; s < 4; ++s) EXPECT_GT(by_status[s], 0) << "status " << s << " never occurred";
}

}  // namespace
}  // namespace eyetrace::optics
