// Phase plates (optics/phase_plate.h): the Cartesian polynomial against the OSA/ANSI Zernike
// polynomials of zernike.h (an independent evaluation), the trace's bending against the
// eikonal rule n d_t' = n d_t - grad W, and the plate on a system with a known answer: on a
// stigmatic surface (no aberration of its own) the traced wavefront is the plate's, and the
// refraction of a defocus or astigmatism plate is the power-vector conversion of Thibos, Hong,
// Bradley & Applegate 2004 (M = -4 sqrt(3) c(2,0) / r^2, J0 = -2 sqrt(6) c(2,2) / r^2, J45 =
// -2 sqrt(6) c(2,-2) / r^2). Measured eyes (the plate at the iris of the Navarro eye) follow.
#include "optics/phase_plate.h"
#include "../support/unity_id.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../support/single_surface.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"
#include "optics/sphero_cylinder.h"
#include "optics/wavefront.h"
#include "optics/zernike.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kSqrt3 = 1.7320508075688772, kSqrt6 = 2.449489742783178;

std::vector<double> unit_term(int j) {
  std::vector<double> c(static_cast<size_t>(j) + 1, 0.0);
  c[j] = 1.0;
  return c;
}

ZernikeFile file_of(std::vector<double> c_um, double pupil_diameter_mm) {
  ZernikeFile f;
  f.origin = "test.zer";
  f.pupil_diameter_mm = pupil_diameter_mm;
  f.max_order = zernike_index(static_cast<int>(c_um.size()) - 1).n;
  c_um.resize(static_cast<size_t>(zernike_term_count(f.max_order)), 0.0);
  f.coefficients_um = c_um;
  return f;
}

TEST(PhasePlate, PolynomialIsTheZernikeSeriesInOsaAxes) {
  const double r = 2.5;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j < zernike_term_count(kMaxZernikeFileOrder); ++j) {
    const PhasePlate plate(unit_term(j), r);
    for (int k = 0; k < 20; ++k) {
      const double x = u(rng) * r * 0.7, y = u(rng) * r * 0.7;
      // 1 um of Z_j is 1e-3 mm; x_osa = -x.
      EXPECT_NEAR(plate.wavefront_mm(x, y), 1e-3 * zernike(j, -x / r, y / r), 1e-12) << "j " << j;
    }
  }
}

TEST(PhasePlate, GradientIsTheDerivativeOfTheSeries) {
  const double r = 3.0, h = 1e-6;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.7, 0.7);
  for (int j = 1; j < zernike_term_count(6); ++j) {
    const PhasePlate plate(unit_term(j), r);
    for (int k = 0; k < 10; ++k) {
      const double x = u(rng) * r, y = u(rng) * r;
      const double dx = 1e-3 * (zernike(j, -(x + h) / r, y / r) - zernike(j, -(x - h) / r, y / r)) / (2 * h);
      const double dy = 1e-3 * (zernike(j, -x / r, (y + h) / r) - zernike(j, -x / r, (y - h) / r)) / (2 * h);
      const glm::dvec2 g = plate.gradient(x, y);
      EXPECT_NEAR(g.x, dx, 1e-8) << "j " << j;
      EXPECT_NEAR(g.y, dy, 1e-8) << "j " << j;
    }
  }
}

// The rho^2 parts of the terms: Z(2,0) = sqrt3 (2 rho^2 - 1), Z(2,2) = sqrt6 (x^2 - y^2),
// Z(2,-2) = 2 sqrt6 x y (OSA axes; the prescription's x is -x_osa), Z(4,0) = sqrt5 (6 rho^4 -
// 6 rho^2 + 1).
TEST(PhasePlate, CurvatureAtTheCentreFromTheSecondOrderParts) {
  const double r = 2.0, c = 0.5, mm = 1e-3 * c / (r * r);
  auto h = [&](int j) {
    std::vector<double> v = unit_term(j);
    v[j] = c;
    return PhasePlate(v, r).hessian_at_centre();
  };
  const PlateHessian d = h(4), a = h(5), o = h(3), s = h(12);
  EXPECT_NEAR(d.xx, 4 * kSqrt3 * mm, 1e-15);
  EXPECT_NEAR(d.yy, 4 * kSqrt3 * mm, 1e-15);
  EXPECT_NEAR(d.xy, 0.0, 1e-15);
  EXPECT_NEAR(a.xx, 2 * kSqrt6 * mm, 1e-15);
  EXPECT_NEAR(a.yy, -2 * kSqrt6 * mm, 1e-15);
  EXPECT_NEAR(o.xy, -2 * kSqrt6 * mm, 1e-15);  // mirrored x
  EXPECT_NEAR(s.xx, -12 * std::sqrt(5.0) * mm, 1e-14);
}

// A plate in air on the stop of the stigmatic surface (single_surface.h).
Prescription plated_surface(const std::vector<double>& c_um, double pupil_radius_mm) {
  Prescription p = test::stigmatic_surface(pupil_radius_mm + 1.0);
  add_phase_plate(p, file_of(c_um, 2.0 * pupil_radius_mm));
  return p;
}

TEST(PhasePlate, TraceBendsByTheGradientAndBlocksOutsideTheDisc) {
  std::vector<double> c(15, 0.0);
  c[4] = 0.8, c[5] = -0.3, c[7] = 0.2, c[12] = 0.1;
  const Prescription p = plated_surface(c, 2.0);
  ASSERT_FALSE(p.rotationally_symmetric());
  const CompiledSystem sys(p);
  ASSERT_FALSE(sys.rotationally_symmetric());
  const PhasePlate& plate = *p.surfaces[0].phase_plate;
  EXPECT_EQ(plate.pupil_magnification, 1.0);  // nothing in front of the stop
  EXPECT_EQ(plate.radius_mm(), 2.0);
  for (const glm::dvec2 at : {glm::dvec2(0.3, -1.1), glm::dvec2(-1.5, 0.9), glm::dvec2(0.0, 0.0)}) {
    Ray ray{{at.x, at.y, -5.0}, {0.0, 0.0, 1.0}};
    const TraceResult t = sys.trace_range(ray, 0, 0);
    ASSERT_TRUE(t.ok());
    // Independent: the series of zernike.h differentiated numerically, in air (n = 1).
    const double h = 1e-6, r = 2.0;
    double wx = 0.0, wy = 0.0;
    for (int j = 0; j < 15; ++j) {
      wx += 1e-3 * c[j] * (zernike(j, -(at.x + h) / r, at.y / r) - zernike(j, -(at.x - h) / r, at.y / r)) / (2 * h);
      wy += 1e-3 * c[j] * (zernike(j, -at.x / r, (at.y + h) / r) - zernike(j, -at.x / r, (at.y - h) / r)) / (2 * h);
    }
    EXPECT_NEAR(t.ray.direction.x, -wx, 1e-9);
    EXPECT_NEAR(t.ray.direction.y, -wy, 1e-9);
    EXPECT_NEAR(t.ray.origin.x, at.x, 1e-12);  // positions unchanged
    EXPECT_NEAR(sys.plate_path_mm(0, t.ray.origin), -plate.wavefront_mm(at.x, at.y), 0.0);
  }
  // The disc ends at the measured pupil: just inside passes, just outside is blocked, although
  // the iris (radius 3 mm) is wider.
  EXPECT_TRUE(sys.trace_forward({{0.0, 1.999, -5.0}, {0.0, 0.0, 1.0}}).ok());
  const TraceResult out = sys.trace_forward({{0.0, 2.001, -5.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(out.status, TraceStatus::StopBlocked);
  EXPECT_EQ(out.surface, 0);
}

TEST(PhasePlate, ReverseTraceUndoesTheForwardOne) {
  std::vector<double> c(15, 0.0);
  c[3] = 0.4, c[6] = -0.5, c[8] = 0.3, c[12] = 0.2, c[14] = -0.1;
  const CompiledSystem sys(plated_surface(c, 2.0));
  for (const glm::dvec2 at : {glm::dvec2(0.7, -1.2), glm::dvec2(-1.6, 0.5)}) {
    const Ray in{{at.x, at.y, -5.0}, glm::normalize(glm::dvec3(0.01, -0.02, 1.0))};
    const TraceResult f = sys.trace_forward(in);
    ASSERT_TRUE(f.ok());
    const TraceResult b = sys.trace_reverse({f.ray.origin, -f.ray.direction});
    ASSERT_TRUE(b.ok());
    EXPECT_NEAR(glm::distance(-b.ray.direction, in.direction), 0.0, 1e-12);
  }
}

TEST(PhasePlate, BendingPastGrazingIsReportedNotNaN) {
  Prescription p = test::stigmatic_surface(3.0);
  // Tilt Z(1,1) = 2 u: grad W = 2 c 1e-3 / r = 2 > 1 with c = 100 um, r = 0.1 mm.
  add_phase_plate(p, file_of({0.0, 0.0, 100.0}, 0.2));
  const CompiledSystem sys(p);
  const TraceResult t = sys.trace_forward({{0.0, 0.05, -5.0}, {0.0, 0.0, 1.0}});
  EXPECT_EQ(t.status, TraceStatus::TotalInternalReflection);
  EXPECT_TRUE(std::isfinite(t.ray.direction.x) && std::isfinite(t.ray.origin.y));
}

TEST(PhasePlate, OnlyOnAFlatSurfaceAndOncePerStop) {
  Prescription p = test::stigmatic_surface(3.0);
  p.surfaces[1].phase_plate = std::make_shared<PhasePlate>(unit_term(4), 2.0);
  EXPECT_THROW(validate(p), OpticsError);
  Prescription q = test::stigmatic_surface(3.0);
  add_phase_plate(q, file_of({0, 0, 0, 0, 0.1}, 4.0));
  EXPECT_THROW(add_phase_plate(q, file_of({0, 0, 0, 0, 0.1}, 4.0)), OpticsError);
}

// A plate alone in air, the image plane L = 1 km behind it: the wavefront leaving the plate is
// -W, so the OPD about the reference sphere (centred on the image point, through the plate's
// centre: the exit pupil is the plate) is W minus the sphere's sag r^2 rho^2 / (2 L), i.e. c(2,0)
// shifted by -r^2 / (4 sqrt(3) L) (the rho^4 part of the sag, r^4 / (8 L^3), is 1e-15 um).
// What is left is second order in the wavefront's slope (1e-3 here): the path from the plate to
// the sphere is taken along each ray, 1/cos(slope) longer than along the sphere's normal (1e-9
// mm where the tilted sphere lies 2e-3 mm off the plate). Piston and tilt are the reference's (the sphere is centred on
// the chief ray's image point, which the plate's gradient at the centre moves) and are not compared.
TEST(PhasePlate, WavefrontOfAPlateInAirIsThePlatesOwn) {
  const double r = 2.0, L = 1e6;
  Prescription p;
  p.name = "plate in air";
  p.media = {{"air", 1.0, 589.3, {}}};
  Surface stop;
  stop.name = "plate", stop.medium = "air", stop.role = SurfaceRole::Stop, stop.semi_diameter_mm = r + 1.0;
  stop.thickness_mm = L;
  Surface image;
  image.name = "image", image.medium = "air", image.role = SurfaceRole::Image;
  p.surfaces = {stop, image};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<double> c(15);
  for (double& v : c) v = u(rng);
  // Directly (add_phase_plate's paraxial analysis refuses the plate-less, afocal system).
  p.surfaces[0].phase_plate = std::make_shared<PhasePlate>(c, r);
  WavefrontOptions o;
  o.pupil_radius_mm = r;
  o.zernike_order = 4;
  const WavefrontResult w = trace_wavefront(p, o);
  EXPECT_EQ(w.rays_lost, 0);
  for (int j = 3; j < 15; ++j)
    EXPECT_NEAR(w.zernike_um[j], c[j] - (j == 4 ? 1e3 * r * r / (4 * kSqrt3 * L) : 0.0), 1e-5) << "j " << j;
  EXPECT_LT(w.fit_residual_waves, 1e-5);
}

TEST(PhasePlate, RefractionOfSecondOrderTermsIsThePowerVectorConversion) {
  const double r = 2.0, c = 0.5;
  const SpheroCylinder plain = refraction_sphero_cylinder(test::stigmatic_surface(3.0));
  for (int j : {3, 4, 5}) {
    std::vector<double> cs(6, 0.0);
    cs[j] = c;
    const SpheroCylinder rx = refraction_sphero_cylinder(plated_surface(cs, r));
    const double m = j == 4 ? -4 * kSqrt3 * c / (r * r) : 0.0;
    const double j0 = j == 5 ? -2 * kSqrt6 * c / (r * r) : 0.0;
    const double j45 = j == 3 ? -2 * kSqrt6 * c / (r * r) : 0.0;
    EXPECT_NEAR(rx.M_D - plain.M_D, m, 1e-9) << "j " << j;
    EXPECT_NEAR(rx.J0_D - plain.J0_D, j0, 1e-9) << "j " << j;
    EXPECT_NEAR(rx.J45_D - plain.J45_D, j45, 1e-9) << "j " << j;
  }
}

// ---- A measured eye: the plate on the Navarro eye's iris ----------------------------------

Prescription navarro(double iris_mm) {
  EyeOptions o;
  o.model = "navarro";
  o.pupil_diameter_mm = iris_mm;
  return make_eye(o);
}

Prescription measured_navarro(const std::vector<double>& c_um, double pupil_mm, double iris_mm) {
  Prescription p = navarro(iris_mm);
  add_phase_plate(p, file_of(c_um, pupil_mm));
  return p;
}

// Thibos et al.'s conversion with the file's r (the entrance pupil's), against the eye's two
// refractions: the report's (sphero_cylinder.h: the plate's curvature at its centre, seen
// through the paraxial pupil magnification 1.133) and the wave report's least squares over the
// measured pupil. The plate's disc is the real image of the measured pupil (magnification 1.114
// at 6 mm, phase_plate.h), so the paraxial one differs by (1.114 / 1.133)^2: 3.2 % of M, 0.012 D
// here; the least squares agree to 1 % (the cornea's pupil distortion).
TEST(PhasePlateEye, SecondOrderTermsGiveThePowerVectorRefraction) {
  const double pupil = 6.0, r = 3.0, c = 0.5;
  const Prescription plain = navarro(6.0);
  WavefrontOptions o;
  o.pupil_radius_mm = r;
  const WavefrontResult w0 = trace_wavefront(plain, o);
  const SpheroCylinder rx0 = refraction_sphero_cylinder(plain);
  for (int j : {3, 4, 5}) {
    std::vector<double> cs(6, 0.0);
    cs[j] = c;
    const Prescription p = measured_navarro(cs, pupil, 6.0);
    const SpheroCylinder rx = refraction_sphero_cylinder(p);
    const WavefrontResult w = trace_wavefront(p, o);
    EXPECT_EQ(w.rays_lost, 0);
    const double m = j == 4 ? -4 * kSqrt3 * c / (r * r) : 0.0;
    const double j0 = j == 5 ? -2 * kSqrt6 * c / (r * r) : 0.0;
    const double j45 = j == 3 ? -2 * kSqrt6 * c / (r * r) : 0.0;
    EXPECT_NEAR(rx.M_D - rx0.M_D, m, 0.05) << "j " << j;
    EXPECT_NEAR(rx.J0_D - rx0.J0_D, j0, 0.05) << "j " << j;
    EXPECT_NEAR(rx.J45_D - rx0.J45_D, j45, 0.05) << "j " << j;
    EXPECT_NEAR(w.least_squares.M_D - w0.least_squares.M_D, m, 0.05) << "j " << j;
    EXPECT_NEAR(w.least_squares.J0_D - w0.least_squares.J0_D, j0, 0.05) << "j " << j;
    EXPECT_NEAR(w.least_squares.J45_D - w0.least_squares.J45_D, j45, 0.05) << "j " << j;
    // The tighter bounds the numbers above explain.
    EXPECT_NEAR(rx.M_D - rx0.M_D + rx.J0_D - rx0.J0_D + rx.J45_D - rx0.J45_D, m + j0 + j45,
                0.035 * std::abs(m + j0 + j45) + 1e-3);
    EXPECT_NEAR(w.least_squares.M_D - w0.least_squares.M_D + w.least_squares.J0_D - w0.least_squares.J0_D +
                    w.least_squares.J45_D - w0.least_squares.J45_D,
                m + j0 + j45, 0.012 * std::abs(m + j0 + j45) + 1e-3);
  }
}

// The wave report's Zernike fit of (eye + plate) minus (eye), over the measured pupil, gives the
// file's coefficients back within 2 % of each plus 3 % of the largest. Why not closer: the
// cornea's pupil distortion maps the plate onto the entrance pupil not quite linearly (the rims
// match, phase_plate.h), which rescales each term a little inside the pupil: measured one term
// at a time, 2.7 % of a 4th-order coefficient moves into the 2nd-order term of the same m, 1 %
// of a 2nd-order one into the 4th order, and a term keeps its own value to 1.2 %. Piston and
// tilt are not compared: the reference sphere follows the chief ray, which the plate's
// gradient at the centre turns.
TEST(PhasePlateEye, WaveReportRecoversTheFilesCoefficients) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  const double pupil = 6.0;
  WavefrontOptions o;
  o.pupil_radius_mm = 0.5 * pupil;
  o.zernike_order = 6;
  const WavefrontResult w0 = trace_wavefront(navarro(6.5), o);
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<double> c(15);
    for (double& v : c) v = u(rng);
    const WavefrontResult w = trace_wavefront(measured_navarro(c, pupil, 6.5), o);
    EXPECT_EQ(w.rays_lost, 0);
    double worst = 0.0, largest = 0.0;
    for (int j = 3; j < 15; ++j) largest = std::max(largest, std::abs(c[j]));
    for (int j = 3; j < 15; ++j) {
      const double d = w.zernike_um[j] - w0.zernike_um[j] - c[j];
      worst = std::max(worst, std::abs(d));
      EXPECT_LE(std::abs(d), 0.02 * std::abs(c[j]) + 0.03 * largest) << "trial " << trial << " j " << j;
    }
    std::printf("trial %d: worst |recovered - file| %.4f um\n", trial, worst);
  }
}

// An iris wider than the measured pupil: the plate passes only what was measured (a note says
// so) and the wave report over the iris's own pupil warns of the blocked rays.
TEST(PhasePlateEye, IrisWiderThanTheMeasuredPupilIsLimitedByThePlate) {
  const Prescription p = measured_navarro({0, 0, 0, 0, 0.2}, 5.0, 6.0);
  ASSERT_FALSE(p.notes.empty());
  EXPECT_NE(p.notes.back().find("wider than the pupil test.zer was measured over"), std::string::npos)
      << p.notes.back();
  const WavefrontResult w = trace_wavefront(p, WavefrontOptions{});
  EXPECT_GT(w.rays_lost, 0);
  EXPECT_FALSE(w.warning.empty());
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
