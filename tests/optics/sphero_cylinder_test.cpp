// The per-meridian (4x4) refraction against outside answers: a Navarro eye whose anterior
// cornea has 1.50 D of cylinder gives the cylinder that each principal meridian's thick-lens
// refraction (2x2 matrices, surface power (n' - n) / R, written here) gives; a symmetric eye has
// no cylinder and its sphere is paraxial.h's refraction; sphero-cylinders and power vectors obey
// Thibos et al. (1997): M = S + C/2, J0 = -C/2 cos 2a, J45 = -C/2 sin 2a; thin obliquely crossed
// cylinders add as power matrices.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/paraxial.h"
#include "optics/report.h"
#include "optics/sphero_cylinder.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kDeg = std::numbers::pi / 180.0;

Prescription navarro() {
  EyeOptions o;
  o.model = "navarro";
  return make_eye(o);
}

using test::meridian_refraction;

// Navarro's eye with the anterior cornea's meridian at axis_deg as published (7.72 mm) and the
// one at axis_deg + 90 steeper by cylinder_D of surface power: (n' - n)(c_cross - c) = C.
Prescription toric_navarro(double cylinder_D, double axis_deg) {
  Prescription p = navarro();
  const SurfaceProfile c = p.surfaces[0].profile;
  const double dn = p.surfaces[0].index_after - 1.0;
  p.surfaces[0].profile =
      SurfaceProfile::biconic(c.curvature, c.conic, c.curvature + cylinder_D / 1000.0 / dn, c.conic, axis_deg);
  return p;
}

TEST(SpheroCylinder, CornealCylinderAtAxis90MatchesThePerMeridianThickLens) {
  const Prescription p = toric_navarro(1.5, 90.0);
  const double c_flat = p.surfaces[0].profile.curvature, c_steep = p.surfaces[0].profile.cross_curvature;
  // The 90 deg meridian has the flat curvature (sphere), the 180 deg one the steep (more myopic).
  const double v90 = meridian_refraction(p, c_flat), v180 = meridian_refraction(p, c_steep);
  const double expected_cylinder = v180 - v90;
  // The anterior cornea lies in the refraction's reference plane: its 1.50 D of cylinder is
  // the refraction's, whatever the rest of the eye (the 2x2 products agree to round-off).
  EXPECT_NEAR(expected_cylinder, -1.5, 1e-9);
  const SpheroCylinder rx = refraction_sphero_cylinder(p);
  EXPECT_NEAR(rx.cylinder_D, expected_cylinder, 0.05);  // the tolerance
  EXPECT_NEAR(rx.cylinder_D, expected_cylinder, 1e-9);  // what it achieves
  EXPECT_NEAR(rx.sphere_D, v90, 1e-9);
  EXPECT_NEAR(rx.axis_deg, 90.0, 1e-9);
  // Power vector (Thibos et al. 1997).
  EXPECT_NEAR(rx.M_D, v90 + expected_cylinder / 2, 1e-9);
  EXPECT_NEAR(rx.J0_D, -expected_cylinder / 2 * std::cos(2 * 90 * kDeg), 1e-9);
  EXPECT_NEAR(rx.J45_D, 0.0, 1e-9);

  // The same numbers reach the optics report (JSON keys of the issue).
  ReportOptions o;
  o.fields_deg = {0.0};
  const nlohmann::json r = optics_report(p, o);
  EXPECT_NEAR(r.at("cylinder_diopters").get<double>(), expected_cylinder, 0.05);
  EXPECT_NEAR(r.at("sphere_diopters").get<double>(), v90, 1e-6);
  EXPECT_NEAR(r.at("axis_deg").get<double>(), 90.0, 1e-6);
  EXPECT_NEAR(r.at("M").get<double>(), rx.M_D, 1e-6);
  EXPECT_NEAR(r.at("J0").get<double>(), rx.J0_D, 1e-6);
  EXPECT_NEAR(r.at("J45").get<double>(), 0.0, 1e-6);
  const std::string text = format_report(r);
  EXPECT_NE(text.find("minus cylinder"), std::string::npos) << text;
  // The real-ray spot still traces (through the general path): rays arrive.
  EXPECT_GT(r.at("spot")[0].at("rays").get<int>(), 0);
}

TEST(SpheroCylinder, ToricLensSurfaceMatchesThePerMeridianThickLens) {
  // Deep in the eye the thick system matters: the lens's back surface (R -6 mm) with a cross
  // meridian of -5.5 mm at axis 60 gives a refraction cylinder well below its surface cylinder.
  Prescription p = navarro();
  const int back = p.image_index() - 1;
  const SurfaceProfile c = p.surfaces[back].profile;
  p.surfaces[back].profile = SurfaceProfile::biconic(c.curvature, c.conic, 1.0 / -5.5, c.conic, 60.0);
  const double v_axis = meridian_refraction(p, c.curvature, back);
  const double v_cross = meridian_refraction(p, 1.0 / -5.5, back);
  const double surface_cylinder = 1000.0 * (p.surfaces[back].index_after - p.surfaces[back - 1].index_after) *
                                  (1.0 / -5.5 - c.curvature);  // power added in the cross meridian
  const SpheroCylinder rx = refraction_sphero_cylinder(p);
  EXPECT_NEAR(rx.cylinder_D, v_cross - v_axis, 1e-9);
  EXPECT_NEAR(rx.sphere_D, v_axis, 1e-9);
  EXPECT_NEAR(rx.axis_deg, 120.0, 1e-9);                                 // 60 deg from +x towards +y is TABO 120
  EXPECT_GT(std::abs(std::abs(rx.cylinder_D) - surface_cylinder), 0.1);  // the thick eye's effect
}

TEST(SpheroCylinder, ObliqueAxisIsTheFlatMeridianInTaboNotation) {
  for (const double axis : {0.0, 30.0, 135.0, 179.0}) {
    const Prescription p = toric_navarro(2.0, axis);
    const double v_axis = meridian_refraction(p, p.surfaces[0].profile.curvature);
    const double v_cross = meridian_refraction(p, p.surfaces[0].profile.cross_curvature);
    const SpheroCylinder rx = refraction_sphero_cylinder(p);
    // The prescription frame's x is mirrored in the clinical frame (ANSI Z80.28, the examiner's
    // view): a meridian at a from +x towards +y is at 180 - a in TABO notation.
    const double tabo = std::fmod(180.0 - axis, 180.0);
    EXPECT_NEAR(rx.sphere_D, v_axis, 1e-9) << axis;
    EXPECT_NEAR(rx.cylinder_D, v_cross - v_axis, 1e-9) << axis;
    EXPECT_NEAR(rx.axis_deg, tabo, 1e-9) << axis;
    EXPECT_NEAR(rx.J0_D, -rx.cylinder_D / 2 * std::cos(2 * tabo * kDeg), 1e-9);
    EXPECT_NEAR(rx.J45_D, -rx.cylinder_D / 2 * std::sin(2 * tabo * kDeg), 1e-9);
  }
}

// The power vector agrees with the one the wavefront section reads from the Zernike coefficients
// of real rays (wavefront.h, "paraxial": curvature at the pupil centre, in the ANSI Z80.28 frame),
// an independent computation: same frame, same signs; the vergence there is at the entrance
// pupil, 3 mm inside the cornea, hence the 0.02 D.
TEST(SpheroCylinder, PowerVectorAgreesWithTheWavefrontsInItsFrame) {
  const Prescription p = toric_navarro(1.5, 30.0);
  const SpheroCylinder rx = refraction_sphero_cylinder(p);
  WavefrontOptions o;
  const WavefrontResult w = trace_wavefront(p, o);
  EXPECT_NEAR(w.paraxial.M_D, rx.M_D, 0.02);
  EXPECT_NEAR(w.paraxial.J0_D, rx.J0_D, 0.02);
  EXPECT_NEAR(w.paraxial.J45_D, rx.J45_D, 0.02);
  EXPECT_GT(std::abs(rx.J45_D), 0.5);  // the test has a J45 whose sign matters
}

TEST(SpheroCylinder, SymmetricEyesHaveNoCylinderAndTheirSphereIsTheRefraction) {
  for (const std::string& model : eye_model_names()) {
    for (const double error : {0.0, -3.0}) {
      EyeOptions o;
      o.model = model;
      o.refractive_error_D = error;
      const Prescription p = make_eye(o);
      const SpheroCylinder rx = refraction_sphero_cylinder(p);
      EXPECT_EQ(rx.cylinder_D, 0.0) << model;
      EXPECT_EQ(rx.axis_deg, 0.0) << model;
      EXPECT_NEAR(rx.sphere_D, refraction_D(p), 1e-9) << model;
      EXPECT_NEAR(rx.M_D, refraction_D(p), 1e-9) << model;
      EXPECT_EQ(rx.J0_D, 0.0);
      EXPECT_EQ(rx.J45_D, 0.0);
    }
  }
}

// Thibos et al. (1997): F = [[S + C sin^2 a, -C sin a cos a], [-C sin a cos a, S + C cos^2 a]].
Mat2 thibos_matrix(double S, double C, double axis_deg) {
  const double a = axis_deg * kDeg, s = std::sin(a), c = std::cos(a);
  return {S + C * s * s, -C * s * c, -C * s * c, S + C * c * c};
}

TEST(SpheroCylinder, PowerMatricesConvertAsThibosWrites) {
  // -2.00 / -1.00 x 90: M = -2.5, J0 = -0.5, J45 = 0.
  SpheroCylinder rx = sphero_cylinder(thibos_matrix(-2.0, -1.0, 90.0));
  EXPECT_NEAR(rx.sphere_D, -2.0, 1e-12);
  EXPECT_NEAR(rx.cylinder_D, -1.0, 1e-12);
  EXPECT_NEAR(rx.axis_deg, 90.0, 1e-12);
  EXPECT_NEAR(rx.M_D, -2.5, 1e-12);
  EXPECT_NEAR(rx.J0_D, -0.5, 1e-12);
  EXPECT_NEAR(rx.J45_D, 0.0, 1e-12);
  // A plus-cylinder prescription +1.00 / +2.00 x 45 is -> +3.00 / -2.00 x 135 in minus cylinder.
  rx = sphero_cylinder(thibos_matrix(1.0, 2.0, 45.0));
  EXPECT_NEAR(rx.sphere_D, 3.0, 1e-12);
  EXPECT_NEAR(rx.cylinder_D, -2.0, 1e-12);
  EXPECT_NEAR(rx.axis_deg, 135.0, 1e-12);
  EXPECT_NEAR(rx.J45_D, -1.0, 1e-12);
  std::mt19937_64 rng(97);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const double S = -10 + 20 * u(rng), C = -0.05 - 5 * u(rng), a = 180 * u(rng);
    rx = sphero_cylinder(thibos_matrix(S, C, a));
    EXPECT_NEAR(rx.sphere_D, S, 1e-12);
    EXPECT_NEAR(rx.cylinder_D, C, 1e-12);
    EXPECT_NEAR(std::remainder(rx.axis_deg - a, 180.0), 0.0, 1e-9);
    EXPECT_GE(rx.axis_deg, 0.0);
    EXPECT_LT(rx.axis_deg, 180.0);
  }
}

TEST(SpheroCylinder, ThinCrossedCylindersAddAsPowerMatrices) {
  // Two biconic surfaces in contact (1e-9 mm apart) in air / glass / air: a thin lens whose
  // power matrix is the sum of the surfaces' (n' - n) times their curvature matrices.
  Prescription p;
  p.name = "crossed";
  Surface stop, a, b, image;
  stop.name = "stop", stop.role = SurfaceRole::Stop, stop.semi_diameter_mm = 2, stop.medium = "air";
  a.name = "front", a.index_after = 1.5, a.medium = "glass", a.thickness_mm = 1e-9;
  a.profile = SurfaceProfile::biconic(1.0 / 100.0, 0.0, 1.0 / 50.0, 0.0, 20.0);
  b.name = "back", b.index_after = 1.0, b.medium = "air", b.thickness_mm = 40.0;
  b.profile = SurfaceProfile::biconic(-1.0 / 80.0, 0.0, 0.0, 0.0, 70.0);
  image.name = "image", image.role = SurfaceRole::Image, image.medium = "air";
  p.surfaces = {stop, a, b, image};
  // Surface powers as sphero-cylinders (D): front 5 in the 20 deg meridian, 10 in the 110 deg
  // one; back (1 - 1.5)(-1/80 mm) = +6.25 in the 70 deg meridian, 0 in the 160 deg one.
  const Mat2 f1 = thibos_matrix(5.0, 5.0, 20.0), f2 = thibos_matrix(6.25, -6.25, 70.0);
  const RayMatrix4 m = system_matrix4(p, 1, 2);
  EXPECT_NEAR(-1000.0 * m.C.xx, f1.xx + f2.xx, 1e-9);
  EXPECT_NEAR(-1000.0 * m.C.xy, f1.xy + f2.xy, 1e-9);
  EXPECT_NEAR(-1000.0 * m.C.yx, f1.yx + f2.yx, 1e-9);
  EXPECT_NEAR(-1000.0 * m.C.yy, f1.yy + f2.yy, 1e-9);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
