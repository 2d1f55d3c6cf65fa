// The shared parts of the reverse-trace stress tests (tests/optics/*_trace_slowtest.cpp): the
// random eyes (every preset, random accommodation, pupil, refractive error, wavelength and
// retina), the random rays from the retina towards the pupil, and the accounting of results
// (finite, unit directions, Ok rays leave through the cornea's clear aperture, lost rays name a
// valid surface). Header-only: the optics tests link the optics library alone.
#pragma once
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "optics/eye_models.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics::test {

// The k-th random eye: the presets in turn, each configuration drawing from `rng` in a fixed
// order (so a seed gives the same eyes and rays every run).
inline EyeOptions random_stress_eye(int k, std::mt19937_64& rng) {
  struct Preset {
    const char* model;
    const char* variant;
  };
  static constexpr Preset kPresets[] = {{"navarro", ""},  {"navarro", "wu2011"}, {"gullstrand", ""}, {"legrand", ""},
                                        {"kooijman", ""}, {"escudero-sanz", ""}, {"arizona", ""}};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Preset& preset = kPresets[k % 7];
  EyeOptions o;
  o.model = preset.model;
  o.variant = preset.variant;
  o.accommodation_D = u(rng) * max_accommodation_D(o.model, o.variant);
  o.pupil_diameter_mm = 0.5 + 8.5 * u(rng);
  if (k % 3 == 0) o.refractive_error_D = -8.0 + 14.0 * u(rng);
  if (k % 4 == 0) o.wavelength_nm = 400.0 + 300.0 * u(rng);
  if (k % 5 == 0) o.retina_radius_mm = -(10.0 + 5.0 * u(rng));
  return o;
}

// A random reverse ray: from a retina point out to 90 deg from the axis, mostly (90 %) towards
// the pupil region (a bit beyond the iris), else anywhere in front.
inline Ray random_reverse_ray(const Prescription& p, const CompiledSystem& sys, double pupil_diameter_mm,
                              std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Surface& retina = p.surfaces.back();
  const double length = p.axial_length_mm();
  const double z_stop = sys.vertex_z(sys.stop_index());
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
  if (u(rng) < 0.9) {
    const double rt = 0.6 * pupil_diameter_mm * std::sqrt(u(rng)), pt = 2.0 * std::numbers::pi * u(rng);
    target = {rt * std::cos(pt), rt * std::sin(pt), z_stop + (u(rng) - 0.5)};
  } else {
    target = {20.0 * (u(rng) - 0.5), 20.0 * (u(rng) - 0.5), length - 30.0 * u(rng)};
  }
  return {at, glm::normalize(target - at)};
}

// Counts the results by status and every way a result can be wrong.
struct StressTally {
  std::array<long, 6> by_status{};  // by TraceStatus (NoConvergence only in non-symmetric systems)
  long unit_failures = 0, aperture_failures = 0, non_finite = 0, bad_surface = 0;

  void add(const TraceResult& t, const Prescription& p, const CompiledSystem& sys) {
    const Surface& cornea = p.surfaces.front();
    const double cornea_sd2 = cornea.semi_diameter_mm * cornea.semi_diameter_mm;
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

  // Nothing wrong, at least `min_total` rays, and every status but TIR seen.
  void expect_clean(long total, long min_total) const {
    EXPECT_GE(total, min_total);
    EXPECT_EQ(non_finite, 0);
    EXPECT_EQ(unit_failures, 0);
    EXPECT_EQ(aperture_failures, 0);
    EXPECT_EQ(bad_surface, 0);
    for (int s = 0; s < 4; ++s) EXPECT_GT(by_status[s], 0) << "status " << s << " never occurred";
  }

 private:
  static bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
};

}  // namespace eyetrace::optics::test
