// Camera directive parameters of the eye and realistic cameras: what each does to the
// prescription, and the messages bad values give (they must name the parameter).
#include "cameras/eye_params.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "cameras/lens_system_camera.h"
#include "optics/paraxial.h"
#include "optics/phase_plate.h"
#include "optics/sphero_cylinder.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Runs the factory of `camera` on the directive's parameters; returns the error message ("" if
// none).
std::string error_of(const std::string& directive, const std::string& search_dir = "") {
  try {
    SceneEntity e = parse_directive_text(directive, "Camera", "test");
    CameraContext ctx{e.params, Transform(), IVec2(32, 32), search_dir};
    if (e.name == "realistic")
      create_realistic_camera(ctx);
    else if (e.name == "eye")
      create_eye_camera(ctx);
    else
      create_named_eye_camera(e.name)(ctx);
  } catch (const SceneError& err) {
    return err.what();
  }
  return "";
}

optics::Prescription prescription_of(const std::string& directive, const std::string& dir = "") {
  SceneEntity e = parse_directive_text(directive, "Camera", "test");
  return prescription_from_camera_params(e.name, e.params, dir);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(EyeParams, UnknownModelListsValidModels) {
  const std::string m = error_of("Camera \"eye\" \"string model\" \"navaro\"");
  EXPECT_TRUE(contains(m, "test:1:")) << m;
  EXPECT_TRUE(contains(m, "parameter \"model\"")) << m;
  EXPECT_TRUE(contains(m, "'navaro'")) << m;
  EXPECT_TRUE(contains(m, "arizona, escudero-sanz, gullstrand, kooijman, legrand, navarro")) << m;
}

TEST(EyeParams, PupilOutsideZeroToTenMillimetresIsAnError) {
  for (const char* value : {"0", "20", "-3"}) {
    const std::string m = error_of(std::string("Camera \"navarro\" \"float pupildiameter\" ") + value);
    EXPECT_TRUE(contains(m, "parameter \"pupildiameter\"")) << m;
    EXPECT_TRUE(contains(m, "(0, 10] mm")) << m;
  }
  EXPECT_EQ(error_of("Camera \"navarro\" \"float pupildiameter\" 10"), "");
}

TEST(EyeParams, AccommodationOutsideTheModelsRangeIsAnError) {
  for (const char* value : {"-1", "1000"}) {
    const std::string m = error_of(std::string("Camera \"navarro\" \"float accommodation\" ") + value);
    EXPECT_TRUE(contains(m, "parameter \"accommodation\"")) << m;
    EXPECT_TRUE(contains(m, "[0, 15] D")) << m;  // Navarro's fit, extrapolated to 15 D
  }
  const std::string k = error_of("Camera \"kooijman\" \"float accommodation\" 1");
  EXPECT_TRUE(contains(k, "parameter \"accommodation\"")) << k;
  EXPECT_TRUE(contains(k, "no accommodation model")) << k;
}

TEST(EyeParams, ViewParametersAreChecked) {
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"float fov\" 0"), "parameter \"fov\""));
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"float fov\" 180"), "parameter \"fov\""));
  const std::string m = error_of("Camera \"navarro\" \"string mapping\" \"fisheye\"");
  EXPECT_TRUE(contains(m, "parameter \"mapping\"") && contains(m, "\"angle\", \"flat\" or \"retina\"")) << m;
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"float sceneunit\" 0"), "parameter \"sceneunit\""));
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"float wavelength\" 0"), "parameter \"wavelength\""));
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"float wavelength\" 2000"), "parameter \"wavelength\""));
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"string variant\" \"wu2012\""), "parameter \"variant\""));
}

// A misspelt parameter is never silently ignored: the camera's parameter check names it and
// suggests the closest declared parameter.
TEST(EyeParams, MisspeltParameterIsReportedWithSuggestion) {
  const std::string m = error_of("Camera \"navarro\" \"float pupildiamter\" 3");
  EXPECT_TRUE(contains(m, "pupildiamter") && contains(m, "did you mean \"pupildiameter\"")) << m;
}

TEST(EyeParams, RetinaShapeAndRadius) {
  // Navarro's default retina is the Escudero-Sanz sphere, R = -12 mm.
  EXPECT_DOUBLE_EQ(prescription_of("Camera \"navarro\"").surfaces.back().profile.curvature, -1.0 / 12.0);
  EXPECT_TRUE(prescription_of("Camera \"navarro\" \"string retina\" \"flat\"").surfaces.back().profile.is_flat());
  EXPECT_DOUBLE_EQ(prescription_of("Camera \"gullstrand\" \"float retinaradius\" 11").surfaces.back().profile.curvature,
                   -1.0 / 11.0);
  EXPECT_TRUE(prescription_of("Camera \"gullstrand\"").surfaces.back().profile.is_flat());
  const std::string m = error_of("Camera \"gullstrand\" \"string retina\" \"curved\"");
  EXPECT_TRUE(contains(m, "parameter \"retina\"") && contains(m, "retinaradius")) << m;
  EXPECT_TRUE(contains(error_of("Camera \"navarro\" \"string retina\" \"flat\" \"float retinaradius\" 12"),
                       "parameter \"retinaradius\""));
}

// Parameters reach the optics: pupil, wavelength, variant, refractive error (a -2 D myope's far
// point is 0.5 m: refraction -2 D).
TEST(EyeParams, ParametersReachThePrescription) {
  const optics::Prescription p = prescription_of(
      "Camera \"eye\" \"string model\" \"navarro\" \"string variant\" \"wu2011\" \"float pupildiameter\" 3.5 "
      "\"float wavelength\" 550");
  EXPECT_DOUBLE_EQ(p.stop_diameter_mm(), 3.5);
  EXPECT_DOUBLE_EQ(p.wavelength_nm, 550.0);
  EXPECT_EQ(p.variant, "wu2011");
  const optics::Prescription myope = prescription_of("Camera \"legrand\" \"float refractiveerror\" -2");
  EXPECT_NEAR(optics::refraction_D(myope), -2.0, 1e-9);
  // Defaults: 4 mm pupil, the model's reference wavelength.
  EXPECT_DOUBLE_EQ(prescription_of("Camera \"navarro\"").stop_diameter_mm(), 4.0);
  EXPECT_DOUBLE_EQ(prescription_of("Camera \"navarro\"").wavelength_nm, 589.3);
}

TEST(EyeParams, RealisticCameraFileErrors) {
  const std::string dir = ::testing::TempDir();
  EXPECT_TRUE(contains(error_of("Camera \"realistic\""), "parameter \"lensfile\""));
  const std::string missing = error_of("Camera \"realistic\" \"string lensfile\" \"no-such-lens.dat\"", dir);
  EXPECT_TRUE(contains(missing, "parameter \"lensfile\"") && contains(missing, "cannot open")) << missing;
  {
    std::ofstream f(dir + "/eyecam_bad.dat");
    f << "50 5 1.5\n";
  }
  const std::string bad = error_of("Camera \"realistic\" \"string lensfile\" \"eyecam_bad.dat\"", dir);
  EXPECT_TRUE(contains(bad, "parameter \"lensfile\"") && contains(bad, "expected 4 or 5 numbers")) << bad;
  {
    std::ofstream f(dir + "/eyecam_ok.dat");
    f << "0 0 0 6\n80 3 1.5 12\n-80 60 0 12\n";
  }
  const std::string inside =
      error_of("Camera \"realistic\" \"string lensfile\" \"eyecam_ok.dat\" \"float focusdistance\" 0.01", dir);
  EXPECT_TRUE(contains(inside, "parameter \"focusdistance\"")) << inside;
  // pbrt-v4 clamps an aperture wider than the stop (with a warning) rather than failing.
  const optics::Prescription p =
      prescription_of("Camera \"realistic\" \"string lensfile\" \"eyecam_ok.dat\" \"float aperturediameter\" 9", dir);
  EXPECT_DOUBLE_EQ(p.stop_diameter_mm(), 6.0);
  EXPECT_DOUBLE_EQ(
      prescription_of("Camera \"realistic\" \"string lensfile\" \"eyecam_ok.dat\"", dir).stop_diameter_mm(),
      1.0);  // pbrt-v4's default aperturediameter
}

// "string zernikefile": the file (relative to the scene's directory) becomes a phase plate on
// the iris; a defocus of 0.5 um over a 6 mm pupil changes the refraction by Thibos et al.'s
// M = -4 sqrt(3) c / r^2 = -0.385 D (optics/phase_plate_test.cpp has the tolerances' reasons).
TEST(EyeParams, ZernikeFileBecomesAPhasePlateOnTheIris) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream f(dir + "/eyecam_defocus.zer");
    f << "pupil_diameter_mm 6\nwavelength_nm 555\nordering osa\n4 0.5\n";
  }
  const optics::Prescription plain = prescription_of("Camera \"navarro\" \"float pupildiameter\" 5");
  const optics::Prescription p = prescription_of(
      "Camera \"navarro\" \"float pupildiameter\" 5 \"string zernikefile\" \"eyecam_defocus.zer\"", dir);
  const optics::PhasePlate* plate = p.surfaces[p.stop_index()].phase_plate.get();
  ASSERT_NE(plate, nullptr);
  EXPECT_FALSE(p.rotationally_symmetric());
  EXPECT_EQ(plate->coefficients_um()[4], 0.5);
  EXPECT_EQ(plate->measured_pupil_diameter_mm, 6.0);
  EXPECT_EQ(plate->measured_wavelength_nm, 555.0);
  const double expected = -4.0 * std::sqrt(3.0) * 0.5 / 9.0;
  EXPECT_NEAR(optics::refraction_sphero_cylinder(p).M_D - optics::refraction_sphero_cylinder(plain).M_D, expected,
              0.05);
  // The camera renders it (symmetric_stand_in.h), the file named relative to the scene.
  const std::string render = error_of("Camera \"navarro\" \"string zernikefile\" \"eyecam_defocus.zer\"", dir);
  EXPECT_TRUE(render.empty()) << render;

  const std::string missing = error_of("Camera \"navarro\" \"string zernikefile\" \"no-such.zer\"", dir);
  EXPECT_TRUE(contains(missing, "parameter \"zernikefile\"") && contains(missing, "no such file")) << missing;
  {
    std::ofstream f(dir + "/eyecam_nan.zer");
    f << "pupil_diameter_mm 6\nordering osa\n4 nan\n";
  }
  const std::string bad = error_of("Camera \"eye\" \"string zernikefile\" \"" + dir + "/eyecam_nan.zer\"", dir);
  EXPECT_TRUE(contains(bad, "test:1:") && contains(bad, "parameter \"zernikefile\"") &&
              contains(bad, "eyecam_nan.zer:3:") && contains(bad, "'nan'"))
      << bad;
}

TEST(EyeParams, OnlyLensCamerasHaveAPrescription) {
  SceneEntity e = parse_directive_text("Camera \"perspective\"", "Camera", "test");
  try {
    prescription_from_camera_params(e.name, e.params, "");
    FAIL();
  } catch (const SceneError& err) {
    EXPECT_TRUE(contains(err.what(), "no lens prescription")) << err.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
