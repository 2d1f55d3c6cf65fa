// Tilted and decentred surfaces and a decentred iris in the sequential trace, against outside
// answers: a tilted plane-parallel plate displaces a ray by the textbook amount
// T sin(i) (1 - cos(i) / sqrt(n^2 - sin^2(i))); a decentred sphere traces like a centred one
// with the ray moved the other way; a decentred iris moves the chief ray of an axial object to
// the image of the stop's centre that a 2x2 paraxial matrix product (written here) predicts.
// A symmetric system keeps the kernel; the general path's batch and per-wavelength traces equal
// its single rays and its system compiled at that wavelength, on every instruction set the batch
// can run on, for the lanes the biconic's lane iteration settles and those it hands on to the
// bracketed search.
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/each_isa.h"
#include "../support/reverse_trace_stress.h"
#include "../support/unity_id.h"
#include "optics/corneal_astigmatism.h"
#include "optics/eye_models.h"
#include "optics/paraxial.h"
#include "optics/phase_plate.h"
#include "optics/sequential_trace.h"
#include "optics/spectacle_lens.h"
#include "optics/zernike_file.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Surface flat(const char* name, double thickness, double index, double sd, SurfaceRole role = SurfaceRole::Refract) {
  Surface s;
  s.name = name;
  s.thickness_mm = thickness;
  s.index_after = index;
  s.medium = index == 1.0 ? "air" : "glass";
  s.semi_diameter_mm = sd;
  s.role = role;
  return s;
}

// A plate of axial thickness t and index n, both faces tilted by the same angles (4 mm clear
// radius: at 40 deg the front face stays clear of the stop 5 mm in front).
Prescription tilted_plate(double t, double n, double tilt_x_deg, double tilt_y_deg) {
  Prescription p;
  p.name = "plate";
  p.surfaces = {flat("stop", 5.0, 1.0, 2.0, SurfaceRole::Stop), flat("front", t, n, 4.0), flat("back", 10.0, 1.0, 4.0),
                flat("image", 0.0, 1.0, 0.0, SurfaceRole::Image)};
  for (int i : {1, 2}) p.surfaces[i].placement.tilt_x_deg = tilt_x_deg, p.surfaces[i].placement.tilt_y_deg = tilt_y_deg;
  return p;
}

TEST(PlacedSurface, TiltedPlateDisplacesARayByTheTextbookAmount) {
  const double t = 3.0, n = 1.5;
  for (const double tilt : {5.0, 20.0, 40.0}) {
    const double i = tilt * std::numbers::pi / 180.0;
    // The faces are parallel planes a distance t cos(i) apart (their vertices are t apart on z).
    const double T = t * std::cos(i);
    const double shift = T * std::sin(i) * (1.0 - std::cos(i) / std::sqrt(n * n - std::sin(i) * std::sin(i)));
    const Ray in{{0.3, -0.2, -1.0}, {0.0, 0.0, 1.0}};
    {
      // tilt_x > 0 turns the faces' normal towards -y: the ray inside bends towards it.
      const CompiledSystem sys(tilted_plate(t, n, tilt, 0.0));
      EXPECT_FALSE(sys.rotationally_symmetric());
      const TraceResult r = sys.trace_forward(in);
      ASSERT_TRUE(r.ok()) << to_string(r.status);
      EXPECT_NEAR(r.ray.origin.y - in.origin.y, -shift, 1e-12) << tilt;
      EXPECT_NEAR(r.ray.origin.x, in.origin.x, 1e-14);
      EXPECT_NEAR(glm::length(r.ray.direction - in.direction), 0.0, 1e-14);  // parallel faces: no deviation
    }
    {
      const CompiledSystem sys(tilted_plate(t, n, 0.0, tilt));  // towards +x
      const TraceResult r = sys.trace_forward(in);
      ASSERT_TRUE(r.ok());
      EXPECT_NEAR(r.ray.origin.x - in.origin.x, shift, 1e-12) << tilt;
      EXPECT_NEAR(r.ray.origin.y, in.origin.y, 1e-14);
    }
  }
}

TEST(PlacedSurface, TiltedExitFaceReflectsTotallyBeyondTheCriticalAngle) {
  // Glass (n = 1.5) to air through a face tilted by i: an axial ray meets it at incidence i, and
  // sin i > 1 / n (i > 41.8 deg) is total internal reflection, reported at that face.
  for (const double tilt : {40.0, 43.0}) {
    Prescription p = tilted_plate(3.0, 1.5, 0.0, 0.0);
    p.surfaces[2].placement.tilt_x_deg = tilt;
    p.surfaces[2].semi_diameter_mm = 2.0;  // clear of the front face at 43 deg
    const TraceResult r = CompiledSystem(p).trace_forward({{0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}});
    const bool tir = std::sin(tilt * std::numbers::pi / 180.0) * 1.5 > 1.0;
    EXPECT_EQ(r.status, tir ? TraceStatus::TotalInternalReflection : TraceStatus::Ok) << tilt;
    if (tir) {
      EXPECT_EQ(r.surface, 2);
    } else {  // Snell: sin(out) = n sin(i) about the tilted normal
      const double i = tilt * std::numbers::pi / 180.0, out = std::asin(1.5 * std::sin(i));
      EXPECT_NEAR(std::acos(r.ray.direction.z), out - i, 1e-12);
    }
  }
}

TEST(PlacedSurface, DecentredSphereTracesLikeTheRayMovedTheOtherWay) {
  Prescription centred;
  centred.name = "sphere";
  Surface lens = flat("lens", 20.0, 1.5, 0.0);
  lens.profile = SurfaceProfile::from_radius(10.0, -0.3);
  centred.surfaces = {flat("stop", 2.0, 1.0, 20.0, SurfaceRole::Stop), lens,
                      flat("image", 0.0, 1.5, 0.0, SurfaceRole::Image)};
  Prescription moved = centred;
  moved.surfaces[1].placement.decentre_x_mm = 0.7;
  moved.surfaces[1].placement.decentre_y_mm = -0.4;
  const CompiledSystem a(centred), b(moved);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Ray r{{3 * u(rng), 3 * u(rng), -1.0}, glm::normalize(glm::dvec3(0.1 * u(rng), 0.1 * u(rng), 1.0))};
    const Ray shifted{r.origin - glm::dvec3(0.7, -0.4, 0.0), r.direction};
    // Through the lens only (the stop is centred in both).
    const TraceResult ta = a.trace_range(shifted, 1, 2), tb = b.trace_range(r, 1, 2);
    ASSERT_EQ(ta.status, tb.status);
    if (!ta.ok()) continue;
    EXPECT_NEAR(glm::length(tb.ray.origin - (ta.ray.origin + glm::dvec3(0.7, -0.4, 0.0))), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(tb.ray.direction - ta.ray.direction), 0.0, 1e-13);
  }
}

// Navarro's eye with its iris moved by (dx, dy).
Prescription navarro_with_iris_at(double dx, double dy, double pupil_mm = 4.0) {
  EyeOptions o;
  o.model = "navarro";
  o.pupil_diameter_mm = pupil_mm;
  Prescription p = make_eye(o);
  p.surfaces[p.stop_index()].placement.decentre_x_mm = dx;
  p.surfaces[p.stop_index()].placement.decentre_y_mm = dy;
  return p;
}

// 2x2 y-nu matrices, written here: refraction by (n' - n) / R, transfer by t / n.
struct M2 {
  double A = 1, B = 0, C = 0, D = 1;
};
M2 mul(const M2& m, const M2& n) {
  return {m.A * n.A + m.B * n.C, m.A * n.B + m.B * n.D, m.C * n.A + m.D * n.C, m.C * n.B + m.D * n.D};
}
M2 through(const Prescription& p, int first, int last_exclusive_transfer_to) {
  M2 m;
  for (int i = first; i < last_exclusive_transfer_to; ++i) {
    const Surface& s = p.surfaces[i];
    const double n_before = i == 0 ? 1.0 : p.surfaces[i - 1].index_after;
    if (s.role == SurfaceRole::Refract && s.profile.curvature != 0.0)
      m = mul(M2{1, 0, -(s.index_after - n_before) / (1.0 / s.profile.curvature), 1}, m);
    m = mul(M2{1, s.thickness_mm / s.index_after, 0, 1}, m);
  }
  return m;
}

// The height at which a ray parallel to the axis crosses the stop plane, as a function of its
// height at the cornea (in the x meridian), inverted by the secant method.
double entering_height_through(const CompiledSystem& sys, double x_stop) {
  auto at_stop = [&](double h) {
    glm::dvec3 points[8];
    const TraceResult r = sys.trace_range({{h, 0.0, -1.0}, {0.0, 0.0, 1.0}}, 0, sys.stop_index(), points);
    return r.ray.origin.x;  // the ray reaches the stop plane (clipped or not, it is there)
  };
  double h0 = 0.0, h1 = x_stop, f0 = at_stop(h0) - x_stop, f1 = at_stop(h1) - x_stop;
  for (int it = 0; it < 50 && std::abs(f1) > 1e-15; ++it) {
    const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
    h0 = h1, f0 = f1, h1 = h2, f1 = at_stop(h2) - x_stop;
  }
  return h1;
}

TEST(PlacedSurface, DecentredIrisMovesTheChiefRayAsParaxialOpticsPredicts) {
  for (const double dx : {0.01, 0.4}) {
    const Prescription p = navarro_with_iris_at(dx, 0.0);
    const CompiledSystem sys(p);
    const int stop = p.stop_index();
    // Paraxially: the stop centre is imaged into object space at x_E = dx / A (A of the matrix
    // from the cornea to the stop plane), so the chief ray of an axial object at infinity enters
    // parallel to the axis at x_E and leaves the lens with the reduced angle n u = C x_E (C of
    // the eye's matrix).
    const M2 to_stop = through(p, 0, stop);
    const double x_entrance = dx / to_stop.A;
    const M2 eye = through(p, 0, p.image_index());
    const double nu_vitreous = eye.C * x_entrance;
    EXPECT_NEAR(paraxial_analysis(p).entrance_pupil.centre_x_mm, x_entrance, 1e-12);
    EXPECT_EQ(paraxial_analysis(p).entrance_pupil.centre_y_mm, 0.0);
    // Real rays: the one through the stop's centre. Pupil aberration grows with the square of
    // the height: 1e-5 relative at 0.01 mm, 2 % at 0.4 mm.
    const double h = entering_height_through(sys, dx);
    const double tol = dx < 0.1 ? 1e-5 : 2e-2;
    EXPECT_NEAR(h, x_entrance, tol * std::abs(x_entrance)) << dx;
    const TraceResult r = sys.trace_forward({{h, 0.0, -1.0}, {0.0, 0.0, 1.0}});
    ASSERT_TRUE(r.ok());
    const double n_vitreous = p.surfaces[p.image_index() - 1].index_after;
    EXPECT_NEAR(n_vitreous * r.ray.direction.x, nu_vitreous, tol * std::abs(nu_vitreous)) << dx;
    EXPECT_NEAR(r.ray.origin.y, 0.0, 1e-15);
  }
}

TEST(PlacedSurface, DecentredIrisPassesItsCentreAndBlocksTheAxis) {
  // A 1 mm iris moved 1.5 mm sideways: the axial ray is blocked at the iris, the chief ray passes.
  const CompiledSystem sys(navarro_with_iris_at(0.0, 1.5, 1.0));
  const TraceResult axial = sys.trace_forward({{0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(axial.status, TraceStatus::StopBlocked);
  EXPECT_EQ(axial.surface, sys.stop_index());
  const double y = paraxial_analysis(navarro_with_iris_at(0.0, 1.5, 1.0)).entrance_pupil.centre_y_mm;
  EXPECT_TRUE(sys.trace_forward({{0.0, y, -1.0}, {0.0, 0.0, 1.0}}).ok());
}

TEST(PlacedSurface, SymmetricSystemsKeepTheKernelAndBiconicEqualsConic) {
  EyeOptions o;
  o.model = "navarro";
  const Prescription p = make_eye(o);
  EXPECT_TRUE(p.rotationally_symmetric());
  EXPECT_TRUE(CompiledSystem(p).rotationally_symmetric());
  // The cornea as a biconic with equal meridians: the general path gives the kernel's rays to
  // round-off.
  Prescription q = p;
  const SurfaceProfile c = q.surfaces[0].profile;
  q.surfaces[0].profile = SurfaceProfile::biconic(c.curvature, c.conic, c.curvature, c.conic, 37.0);
  EXPECT_FALSE(q.rotationally_symmetric());
  const CompiledSystem a(p), b(q);
  EXPECT_FALSE(b.rotationally_symmetric());
  std::mt19937_64 rng(11);
  int ok = 0;
  for (int k = 0; k < 3000; ++k) {
    const Ray r = test::random_reverse_ray(p, a, 4.0, rng);
    const TraceResult ta = a.trace_reverse(r), tb = b.trace_reverse(r);
    ASSERT_EQ(ta.status, tb.status) << k;
    if (!ta.ok()) continue;
    ++ok;
    EXPECT_NEAR(glm::length(ta.ray.origin - tb.ray.origin), 0.0, 1e-11);
    EXPECT_NEAR(glm::length(ta.ray.direction - tb.ray.direction), 0.0, 1e-11);
  }
  EXPECT_GT(ok, 1000);
}

TEST(PlacedSurface, GeneralBatchAndWavelengthTracesEqualSingleRaysBitForBit) {
  Prescription p = navarro_with_iris_at(0.2, -0.1);
  const SurfaceProfile c = p.surfaces[0].profile;
  p.surfaces[0].profile = SurfaceProfile::biconic(c.curvature, c.conic, 1.0 / 7.5, -0.2, 15.0);
  p.surfaces[4].placement.tilt_y_deg = 2.0;  // the lens's back surface
  const CompiledSystem sys(p);
  const CompiledSystem blue(at_wavelength(p, 450.0));
  std::mt19937_64 rng(5);
  std::vector<Ray> rays(100);
  for (Ray& r : rays) r = test::random_reverse_ray(p, sys, 4.0, rng);
  std::vector<TraceResult> batch(rays.size()), at450(rays.size());
  std::vector<double> lambda(rays.size(), 450.0);
  sys.trace_reverse_batch(rays.data(), batch.data(), rays.size());
  sys.trace_range_batch(rays.data(), lambda.data(), at450.data(), rays.size(), sys.image_index() - 1, 0);
  int ok = 0;
  for (size_t j = 0; j < rays.size(); ++j) {
    const TraceResult one = sys.trace_reverse(rays[j]), compiled = blue.trace_reverse(rays[j]);
    EXPECT_EQ(batch[j].status, one.status);
    EXPECT_EQ(batch[j].surface, one.surface);
    EXPECT_EQ(batch[j].ray.origin, one.ray.origin);
    EXPECT_EQ(batch[j].ray.direction, one.ray.direction);
    EXPECT_EQ(at450[j].status, compiled.status);
    EXPECT_EQ(at450[j].ray.origin, compiled.ray.origin);
    EXPECT_EQ(at450[j].ray.direction, compiled.ray.direction);
    const TraceResult per_ray = sys.trace_range(rays[j], sys.image_index() - 1, 0, 450.0);
    EXPECT_EQ(at450[j].surface, per_ray.surface);
    EXPECT_EQ(at450[j].ray.origin, per_ray.ray.origin);
    EXPECT_EQ(at450[j].ray.direction, per_ray.ray.direction);
    ok += one.ok();
  }
  EXPECT_GT(ok, 30);
  // Forward, object -> image: the rays that left, turned round.
  std::vector<Ray> in;
  for (const TraceResult& r : batch)
    if (r.ok()) in.push_back({r.ray.origin + r.ray.direction, -r.ray.direction});
  std::vector<TraceResult> fwd(in.size());
  std::vector<double> lambdas(in.size());
  for (size_t j = 0; j < in.size(); ++j) lambdas[j] = 400.0 + 3.0 * double(j);
  sys.trace_range_batch(in.data(), lambdas.data(), fwd.data(), in.size(), 0, sys.image_index());
  for (size_t j = 0; j < in.size(); ++j) {
    const TraceResult one = sys.trace_range(in[j], 0, sys.image_index(), lambdas[j]);
    EXPECT_EQ(fwd[j].status, one.status);
    EXPECT_EQ(fwd[j].ray.origin, one.ray.origin);
    EXPECT_EQ(fwd[j].ray.direction, one.ray.direction);
  }
}

using eyetrace::test::EachIsa;

// Every lane of trace_range_batch against trace_range for the same ray (and wavelength).
void expect_batch_bits(const CompiledSystem& sys, const std::vector<Ray>& rays, const std::vector<double>* lambda,
                       int first, int last, const std::string& what) {
  std::vector<TraceResult> batch(rays.size());
  sys.trace_range_batch(rays.data(), lambda ? lambda->data() : nullptr, batch.data(), rays.size(), first, last);
  for (size_t j = 0; j < rays.size(); ++j) {
    const TraceResult one =
        lambda ? sys.trace_range(rays[j], first, last, (*lambda)[j]) : sys.trace_range(rays[j], first, last);
    ASSERT_EQ(batch[j].status, one.status) << what << " ray " << j;
    ASSERT_EQ(batch[j].surface, one.surface) << what << " ray " << j;
    ASSERT_EQ(batch[j].ray.origin, one.ray.origin) << what << " ray " << j;
    ASSERT_EQ(batch[j].ray.direction, one.ray.direction) << what << " ray " << j;
  }
}

// The eye: a -3 D myope with 1.5 D of corneal cylinder at 30 deg, its iris decentred,
// behind toric spectacles (two biconic surfaces, the cornea and the lens's back, both traced by
// the batch's lane kernel), in reverse at the compiled wavelength and at mixed per-ray ones.
// And a cylinder (one flat meridian) crossed by rays from all sides: many miss its start conic
// (the curved meridian's sphere) or cross it twice, the lanes the batch's first stage hands on to
// the bracketed search one at a time, so both stages are compared.
TEST(PlacedSurface, BatchOnEveryInstructionSetEqualsSingleRaysBitForBit) {
  EyeOptions o;
  o.model = "navarro";
  o.refractive_error_D = -3.0;
  o.pupil_diameter_mm = 6.0;
  Prescription eye = make_eye(o);
  set_corneal_cylinder(eye, -1.5, 30.0);
  set_pupil_decentration(eye, 0.3, -0.2);
  SpectacleLens lens;
  lens.sphere_D = -3.1, lens.cylinder_D = -1.5, lens.axis_deg = 30.0;
  add_spectacle_lens(eye, lens);
  const CompiledSystem sys(eye);
  ASSERT_FALSE(sys.rotationally_symmetric());
  // The same with a measured wavefront (coma and astigmatism, third order) on the iris: a phase
  // plate's surface, which the batch takes lane by lane.
  ZernikeFile zernike;
  zernike.origin = "test.zer";
  zernike.pupil_diameter_mm = 6.0;
  zernike.max_order = 3;
  zernike.coefficients_um = {0.0, 0.0, 0.0, 0.2, 0.1, -0.3, 0.0, 0.15, -0.1, 0.0};
  Prescription plated_eye = eye;
  add_phase_plate(plated_eye, zernike);
  const CompiledSystem plated(plated_eye);

  Prescription cyl;
  cyl.name = "cylinder";
  cyl.surfaces = {flat("stop", 1.0, 1.0, 20.0, SurfaceRole::Stop), flat("cylinder", 8.0, 1.5, 0.0),
                  flat("image", 0.0, 1.5, 0.0, SurfaceRole::Image)};
  cyl.surfaces[1].profile = SurfaceProfile::biconic(1.0 / 4.0, 0.0, 0.0, 0.0, 30.0);
  const CompiledSystem cylinder(cyl);

  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Ray> reverse(333), forward(333);
  std::vector<double> lambda(reverse.size());
  for (size_t j = 0; j < reverse.size(); ++j) {
    reverse[j] = test::random_reverse_ray(eye, sys, 8.0, rng);
    lambda[j] = 400.0 + 300.0 * (0.5 + 0.5 * u(rng));
    forward[j] = {{6.0 * u(rng), 6.0 * u(rng), -2.0 + u(rng)}, {u(rng), u(rng), 0.2 + u(rng)}};
  }
  EachIsa each;
  for (TraceBatchIsa isa : each.isas) {
    ASSERT_TRUE(set_trace_batch_isa(isa));
    const std::string name = to_string(isa);
    expect_batch_bits(sys, reverse, nullptr, sys.image_index() - 1, 0, name + " eye");
    expect_batch_bits(sys, reverse, &lambda, sys.image_index() - 1, 0, name + " eye per-ray wavelength");
    expect_batch_bits(plated, reverse, &lambda, plated.image_index() - 1, 0, name + " eye with a phase plate");
    expect_batch_bits(cylinder, forward, nullptr, 0, cylinder.image_index(), name + " cylinder");
  }
  // The comparison covers passing and lost rays of both systems.
  int eye_ok = 0, cylinder_ok = 0, cylinder_lost = 0;
  int plated_ok = 0;
  for (const Ray& r : reverse) eye_ok += sys.trace_reverse(r).ok(), plated_ok += plated.trace_reverse(r).ok();
  for (const Ray& r : forward) (cylinder.trace_forward(r).ok() ? cylinder_ok : cylinder_lost) += 1;
  EXPECT_GT(eye_ok, 50);
  EXPECT_LT(eye_ok, 330);
  EXPECT_GT(plated_ok, 50);
  EXPECT_GT(cylinder_ok, 30);
  EXPECT_GT(cylinder_lost, 30);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
