// A person's eye on the eye cameras (issue 16 parts 2 and 3): the camera parameters ametropia,
// cylinder, axis, pupildecentration, age, spectacle* and contactlens, checked with numbers a
// clinician knows through the optics report that `eyetrace optics --camera` prints (its paraxial
// refraction), against refractions computed independently here (y-nu traces of
// tests/support/meridian_refraction.h, the vertex-distance formula F / (1 + d F)); and bad values,
// whose errors must name the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "cameras/eye_params.h"
#include "cameras/lens_system_camera.h"
#include "optics/report.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string error_of(const std::string& directive) {
  try {
    SceneEntity e = parse_directive_text(directive, "Camera", "test");
    CameraContext ctx{e.params, Transform(), IVec2(32, 32), ""};
    create_named_eye_camera(e.name)(ctx);
  } catch (const SceneError& err) {
    return err.what();
  }
  return "";
}

optics::Prescription prescription_of(const std::string& directive) {
  SceneEntity e = parse_directive_text(directive, "Camera", "test");
  return prescription_from_camera_params(e.name, e.params, "");
}

// The refraction part of the optics report (what `eyetrace optics --json` prints).
nlohmann::json report_of(const std::string& directive) {
  optics::ReportOptions o;
  o.fields_deg = {0.0};
  return optics::optics_report(prescription_of(directive), o);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(EyeParamsPrescription, AxialAndRefractiveAmetropiaGiveTheRefraction) {
  const optics::Prescription plain = prescription_of("Camera \"navarro\"");
  for (const double error : {-3.0, 2.0}) {
    const std::string base = "Camera \"navarro\" \"float refractiveerror\" " + std::to_string(error);
    const nlohmann::json axial = report_of(base), refractive = report_of(base + " \"string ametropia\" \"refractive\"");
    EXPECT_NEAR(axial["refraction_diopters"].get<double>(), error, 0.01);
    EXPECT_NEAR(refractive["refraction_diopters"].get<double>(), error, 0.01);
    EXPECT_NEAR(refractive["sphere_diopters"].get<double>(), error, 0.01);
    // Axial: a myope's eye is longer (about 0.37 mm per dioptre in Navarro's), cornea unchanged;
    // refractive: the length is the model's, the cornea steeper for a myope.
    EXPECT_NEAR(axial["axial_length_mm"].get<double>() - plain.axial_length_mm(), -0.38 * error, 0.1 * std::abs(error));
    EXPECT_NEAR(refractive["axial_length_mm"].get<double>(), plain.axial_length_mm(), 1e-9);
    const double r0 = 1.0 / plain.surfaces[0].profile.curvature;
    EXPECT_EQ(1.0 / prescription_of(base).surfaces[0].profile.curvature, r0);
    const double r = 1.0 / prescription_of(base + " \"string ametropia\" \"refractive\"").surfaces[0].profile.curvature;
    EXPECT_EQ(r < r0, error < 0.0) << r << " vs " << r0;
  }
}

TEST(EyeParamsPrescription, SpectacleAtTwelveMillimetresCorrectsAMinusThreeMyope) {
  // -3 / (1 - 0.012 x 3) = -3.112 D: the vertex-distance formula.
  const double lens = -3.0 / (1.0 - 0.012 * 3.0);
  const std::string eye = "Camera \"navarro\" \"float refractiveerror\" -3";
  const nlohmann::json r = report_of(eye + " \"float spectaclesphere\" " + std::to_string(lens));
  EXPECT_NEAR(r["refraction_diopters"].get<double>(), 0.0, 0.05);
  EXPECT_NEAR(r["M"].get<double>(), 0.0, 0.05);
  // A -3.00 D lens at 12 mm (no vertex correction) brings -3 / (1 + 0.012 x 3) = -2.896 D to the
  // cornea: -0.104 D is left (the far point, 9.6 m away, is as far from the lens).
  const nlohmann::json under = report_of(eye + " \"float spectaclesphere\" -3");
  EXPECT_NEAR(under["refraction_diopters"].get<double>(), -3.0 + 3.0 / (1.0 + 0.012 * 3.0), 0.01);
  // The camera renders it (rotationally symmetric).
  EXPECT_EQ(error_of(eye + " \"float spectaclesphere\" -3.112"), "");
}

TEST(EyeParamsPrescription, ContactLensCorrectsAMinusThreeMyope) {
  const std::string eye = "Camera \"navarro\" \"float refractiveerror\" -3";
  const nlohmann::json r = report_of(eye + " \"float contactlens\" -3");
  EXPECT_NEAR(r["refraction_diopters"].get<double>(), 0.0, 0.05);
  EXPECT_NEAR(r["sphere_diopters"].get<double>(), 0.0, 0.05);
  EXPECT_EQ(error_of(eye + " \"float contactlens\" -3"), "");
}

TEST(EyeParamsPrescription, CornealCylinderMatchesThePerMeridianFormula) {
  for (const char* sign : {"-1.5", "1.5"}) {
    const std::string d = std::string("Camera \"navarro\" \"float cylinder\" ") + sign + " \"float axis\" 90";
    const optics::Prescription p = prescription_of(d);
    // TABO 90 and 180 are the prescription frame's 90 and 0 (x mirrored); the refraction in each.
    const double f90 = optics::test::meridian_refraction_at(p, 90.0),
                 f180 = optics::test::meridian_refraction_at(p, 0.0);
    const double sphere = std::max(f90, f180), cylinder = std::min(f90, f180) - sphere;
    const double axis = f90 >= f180 ? 90.0 : 0.0;
    const nlohmann::json r = report_of(d);
    EXPECT_NEAR(r["cylinder_diopters"].get<double>(), cylinder, 0.05) << sign;
    EXPECT_NEAR(r["cylinder_diopters"].get<double>(), -1.5, 0.05) << sign;
    EXPECT_NEAR(r["sphere_diopters"].get<double>(), sphere, 0.05) << sign;
    EXPECT_NEAR(r["axis_deg"].get<double>(), axis, 0.5) << sign;
  }
}

TEST(EyeParamsPrescription, SpectacleCylinderCorrectsTheCornealCylinder) {
  const std::string eye = "Camera \"navarro\" \"float refractiveerror\" -3 \"float cylinder\" -1.5 \"float axis\" 90";
  const optics::Prescription p = prescription_of(eye);
  auto at_12mm = [](double f) { return f / (1.0 + 0.012 * f); };
  const double s = at_12mm(optics::test::meridian_refraction_at(p, 90.0));
  const double c = at_12mm(optics::test::meridian_refraction_at(p, 0.0)) - s;
  const nlohmann::json r =
      report_of(eye + " \"float spectaclesphere\" " + std::to_string(s) + " \"float spectaclecylinder\" " +
                std::to_string(c) + " \"float spectacleaxis\" 90");
  EXPECT_LT(std::abs(r["cylinder_diopters"].get<double>()), 0.05);
  EXPECT_LT(std::abs(r["M"].get<double>()), 0.05);
  EXPECT_LT(std::abs(report_of(eye)["cylinder_diopters"].get<double>() + 1.5), 0.05);  // uncorrected
}

TEST(EyeParamsPrescription, SixtyYearOldRefusesSixDioptres) {
  const std::string m = error_of("Camera \"navarro\" \"float age\" 60 \"float accommodation\" 6");
  EXPECT_TRUE(contains(m, "parameter \"accommodation\"")) << m;
  EXPECT_TRUE(contains(m, "60-year-old")) << m;
  EXPECT_TRUE(contains(m, "Hofstetter's (1950) maximum-amplitude relation 25 - 0.4 x age")) << m;
  EXPECT_TRUE(contains(m, "1.00 D")) << m;
  EXPECT_EQ(error_of("Camera \"navarro\" \"float age\" 20 \"float accommodation\" 6"), "");
}

TEST(EyeParamsPrescription, PupilDecentrationMovesTheIris) {
  const optics::Prescription p = prescription_of("Camera \"navarro\" \"float pupildecentration\" [0.5 -0.25]");
  const optics::Surface& iris = p.surfaces[p.stop_index()];
  EXPECT_EQ(iris.placement.decentre_x_mm, 0.5);
  EXPECT_EQ(iris.placement.decentre_y_mm, -0.25);
}

TEST(EyeParamsPrescription, BadValuesNameTheParameter) {
  const std::pair<const char*, const char*> cases[] = {
      {"\"float axis\" 190 \"float cylinder\" -1", "parameter \"axis\": 190 deg is outside [0, 180] deg"},
      {"\"float spectaclesphere\" -2 \"float spectacleaxis\" -5", "parameter \"spectacleaxis\": -5 deg is outside"},
      {"\"float spectaclesphere\" 6 \"float spectaclethickness\" 2",
       "parameter \"spectaclethickness\": the lens's surfaces meet inside its 50 mm diameter"},
      {"\"float spectaclesphere\" -3 \"float vertexdistance\" 0", "parameter \"vertexdistance\": 0 mm is outside"},
      {"\"float spectaclesphere\" -3 \"float vertexdistance\" -4", "parameter \"vertexdistance\": -4 mm is outside"},
      {"\"float vertexdistance\" 12", "parameter \"vertexdistance\": there is no spectacle lens"},
      {"\"float age\" -1", "parameter \"age\": -1 years is outside [0, 120] years"},
      {"\"float age\" nan", "\"nan\" is not a finite number"},
      {"\"float cylinder\" nan", "\"nan\" is not a finite number"},
      {"\"float pupildecentration\" [4 0]", "parameter \"pupildecentration\": 4 mm is outside [-3, 3] mm"},
      {"\"float pupildecentration\" [1]", "parameter \"pupildecentration\" takes 2 values"},
      {"\"string ametropia\" \"corneal\"", "parameter \"ametropia\": \"corneal\" is not one of"},
      {"\"float contactlens\" 30", "parameter \"contactlens\": 30 D is outside [-20, 20] D"},
      {"\"float refractiveerror\" -30 \"string ametropia\" \"refractive\"", "parameter \"refractiveerror\""},
  };
  for (const auto& [params, expected] : cases) {
    const std::string m = error_of(std::string("Camera \"navarro\" ") + params);
    EXPECT_TRUE(contains(m, expected)) << params << "\n  got: " << m;
    EXPECT_TRUE(contains(m, "test:1:")) << m;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
