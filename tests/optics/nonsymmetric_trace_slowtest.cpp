// Stress test of the general (non-symmetric) trace path: 10 million random rays per eye through
// Navarro's and Le Grand's eyes with a toric (biconic) anterior cornea, a decentred and tilted
// crystalline lens and a decentred iris (random cylinder 0.25-4 D at a random axis, lens
// surfaces decentred up to 0.3 mm and tilted up to 3 deg, iris up to 0.5 mm off the axis, pupil
// 1-8 mm), reverse (retina -> world, as the eye camera traces) and forward (world -> retina).
// Every result must be finite with a unit direction; every Ok reverse ray must lie on the
// cornea's biconic sheet inside its clear aperture, every Ok forward ray on the retina; lost
// rays are counted by kind and printed, and must name a valid surface.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
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

// The k-th random non-symmetric eye of a model.
Prescription random_astigmatic_eye(const char* model, std::mt19937_64& rng, double& pupil_mm) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  EyeOptions o;
  o.model = model;
  o.pupil_diameter_mm = pupil_mm = 1.0 + 7.0 * u(rng);
  Prescription p = make_eye(o);
  // Toric cornea: the cross meridian steeper by 0.25-4 D of surface power.
  const SurfaceProfile c = p.surfaces[0].profile;
  const double cylinder_D = 0.25 + 3.75 * u(rng), dn = p.surfaces[0].index_after - 1.0;
  p.surfaces[0].profile =
      SurfaceProfile::biconic(c.curvature, c.conic, c.curvature + cylinder_D / 1000.0 / dn, c.conic, 180.0 * u(rng));
  // The iris 0.3 mm in front of the lens (room for the tilted lens), decentred.
  const int stop = p.stop_index();
  p.surfaces[stop - 1].thickness_mm -= 0.3;
  p.surfaces[stop].thickness_mm += 0.3;
  p.surfaces[stop].placement.decentre_x_mm = 0.5 * (2.0 * u(rng) - 1.0);
  p.surfaces[stop].placement.decentre_y_mm = 0.5 * (2.0 * u(rng) - 1.0);
  // The lens's surfaces (all between the iris and the retina) decentred and tilted alike.
  const double dx = 0.3 * (2.0 * u(rng) - 1.0), dy = 0.3 * (2.0 * u(rng) - 1.0);
  const double tx = 3.0 * (2.0 * u(rng) - 1.0), ty = 3.0 * (2.0 * u(rng) - 1.0);
  for (int i = stop + 1; i < p.image_index(); ++i) p.surfaces[i].placement = {dx, dy, tx, ty};
  return p;
}

// A random forward ray: from 5 mm in front of the cornea towards a point near the pupil, within
// 60 deg of the axis.
Ray random_forward_ray(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double theta = 60.0 * std::numbers::pi / 180.0 * std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
  const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  const glm::dvec3 target(6.0 * (u(rng) - 0.5), 6.0 * (u(rng) - 0.5), 3.6);
  return {target - (3.6 + 5.0) / d.z * d, d};
}

struct Tally {
  std::array<long, 6> by_status{};
  long non_finite = 0, unit_failures = 0, off_surface = 0, bad_surface = 0;
};

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check(const TraceResult& t, const Prescription& p, const CompiledSystem& sys, bool reverse, Tally& n) {
  ++n.by_status[static_cast<int>(t.status)];
  if (!finite(t.ray.origin) || !finite(t.ray.direction)) ++n.non_finite;
  if (std::abs(glm::length(t.ray.direction) - 1.0) > 1e-12) ++n.unit_failures;
  if (!t.ok()) {
    if (t.surface < 0 || t.surface > sys.image_index()) ++n.bad_surface;
    return;
  }
  const glm::dvec3& q = t.ray.origin;
  if (reverse) {  // on the cornea's biconic sheet, inside its aperture
    const Surface& cornea = p.surfaces[0];
    const double r2 = q.x * q.x + q.y * q.y;
    if (t.surface != 0 || r2 > cornea.semi_diameter_mm * cornea.semi_diameter_mm * (1 + 1e-12) ||
        std::abs(q.z - cornea.profile.sag(q.x, q.y)) > 1e-9)
      ++n.off_surface;
  } else {  // on the retina's sphere
    const double R = 1.0 / p.surfaces.back().profile.curvature;
    const glm::dvec3 centre(0.0, 0.0, sys.vertex_z(sys.image_index()) + R);
    if (t.surface != sys.image_index() || std::abs(glm::length(q - centre) - std::abs(R)) > 1e-9) ++n.off_surface;
  }
}

void stress(const char* model, std::uint64_t seed) {
  constexpr int kEyes = 100, kRaysPerEye = 100000;  // 10 million rays
  std::mt19937_64 rng(seed);
  Tally n;
  const auto start = std::chrono::steady_clock::now();
  std::vector<Ray> rays(kRaysPerEye);
  std::vector<TraceResult> results(kRaysPerEye);
  for (int k = 0; k < kEyes; ++k) {
    double pupil_mm = 0.0;
    const Prescription p = random_astigmatic_eye(model, rng, pupil_mm);
    const CompiledSystem sys(p);
    ASSERT_FALSE(sys.rotationally_symmetric());
    const bool reverse = k % 4 != 3;  // three quarters reverse, as the camera traces
    for (Ray& r : rays) r = reverse ? test::random_reverse_ray(p, sys, pupil_mm, rng) : random_forward_ray(rng);
    if (reverse)
      sys.trace_reverse_batch(rays.data(), results.data(), rays.size());
    else
      for (size_t j = 0; j < rays.size(); ++j) results[j] = sys.trace_forward(rays[j]);
    for (const TraceResult& t : results) check(t, p, sys, reverse, n);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long total = static_cast<long>(kEyes) * kRaysPerEye;
  const auto& s = n.by_status;
  std::printf(
      "%s: %ld rays in %.2f s (%.2f M/s incl. generation and checks): ok %ld, missed %ld, vignetted %ld, stop %ld, "
      "TIR %ld, no convergence %ld\n",
      model, total, seconds, total / seconds / 1e6, s[0], s[1], s[2], s[3], s[4], s[5]);
  EXPECT_EQ(total, 10'000'000);
  EXPECT_EQ(n.non_finite, 0);
  EXPECT_EQ(n.unit_failures, 0);
  EXPECT_EQ(n.off_surface, 0);
  EXPECT_EQ(n.bad_surface, 0);
  EXPECT_GT(s[0], total / 4);  // most rays aimed at the pupil pass
  for (int i = 1; i < 4; ++i) EXPECT_GT(s[i], 0) << "status " << i << " never occurred";
}

TEST(NonSymmetricTraceStress, NavarroTenMillionRandomRays) { stress("navarro", 20261125); }
TEST(NonSymmetricTraceStress, LeGrandTenMillionRandomRays) { stress("legrand", 20261126); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
