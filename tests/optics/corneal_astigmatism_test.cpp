// Corneal astigmatism for the eye camera's cylinder and axis: the cornea's own surface powers
// ((n' - n) / R per meridian) are checked against the radii it sets; the eye's refraction has
// the cylinder that each meridian's 2x2 thick-lens product gives, which is the corneal cylinder
// itself (the anterior cornea lies in the refraction's reference plane: a power added there
// adds to the refraction unchanged), and its sphere is the symmetric eye's refraction; the pupil
// decentration lands on the stop. Bad values name the option.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "optics/corneal_astigmatism.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sphero_cylinder.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription eye(const char* model) {
  EyeOptions o;
  o.model = model;
  return make_eye(o);
}

TEST(CornealAstigmatism, CornealCylinderSetsTheSurfacePowersAndTheEyeFollows) {
  for (const char* model : {"navarro", "legrand", "gullstrand"}) {
    Prescription p = eye(model);
    const double c = p.surfaces[0].profile.curvature, n = p.surfaces[0].index_after;
    set_corneal_cylinder(p, -1.5, 90.0);
    const SurfaceProfile& s = p.surfaces[0].profile;
    EXPECT_EQ(s.kind, ProfileKind::Biconic);
    EXPECT_EQ(s.curvature, c);
    EXPECT_NEAR(1000.0 * (n - 1.0) * (s.cross_curvature - s.curvature), 1.5, 1e-12) << model;
    const double v90 = test::meridian_refraction(p, s.curvature),
                 v180 = test::meridian_refraction(p, s.cross_curvature);
    const SpheroCylinder rx = refraction_sphero_cylinder(p);
    EXPECT_NEAR(rx.cylinder_D, v180 - v90, 0.05) << model;
    EXPECT_NEAR(rx.cylinder_D, v180 - v90, 1e-9) << model;
    EXPECT_NEAR(rx.axis_deg, 90.0, 1e-9);
    EXPECT_NEAR(rx.sphere_D, refraction_D(eye(model)), 1e-9);
    EXPECT_NEAR(rx.cylinder_D, -1.5, 1e-9);  // the corneal cylinder, at the corneal vertex
  }
}

TEST(CornealAstigmatism, AnyAxisAndSignInMinusCylinderForm) {
  for (const double axis : {0.0, 45.0, 90.0, 163.0, 180.0}) {
    for (const double cylinder : {-0.25, -1.5, -4.0, 2.0}) {
      Prescription p = eye("navarro");
      set_corneal_cylinder(p, cylinder, axis);
      const SpheroCylinder rx = refraction_sphero_cylinder(p);
      // Minus-cylinder form: a plus cylinder C at a is sphere + C, -C at a + 90.
      const double a = axis == 180.0 ? 0.0 : axis;
      const double expected_axis = cylinder < 0 ? a : std::fmod(a + 90.0, 180.0);
      const double expected_sphere = refraction_D(eye("navarro")) + (cylinder < 0 ? 0.0 : cylinder);
      EXPECT_NEAR(rx.cylinder_D, -std::abs(cylinder), 1e-9) << axis << " " << cylinder;
      EXPECT_NEAR(rx.axis_deg, expected_axis, 1e-7) << axis << " " << cylinder;
      EXPECT_NEAR(rx.sphere_D, expected_sphere, 1e-9) << axis << " " << cylinder;
    }
  }
  Prescription p = eye("navarro");
  set_corneal_cylinder(p, 0.0, 30.0);  // no cylinder: the symmetric eye
  EXPECT_TRUE(p.rotationally_symmetric());
}

TEST(CornealAstigmatism, PupilDecentrationMovesTheStop) {
  Prescription p = eye("navarro");
  set_pupil_decentration(p, 0.4, -0.2);
  EXPECT_EQ(p.surfaces[p.stop_index()].placement.decentre_x_mm, 0.4);
  EXPECT_EQ(p.surfaces[p.stop_index()].placement.decentre_y_mm, -0.2);
  EXPECT_FALSE(p.rotationally_symmetric());
}

TEST(CornealAstigmatism, BadValuesNameTheOption) {
  auto expect_option = [](auto f, const std::string& option, const std::string& message) {
    Prescription p = eye("navarro");
    try {
      f(p);
      ADD_FAILURE() << "no error for " << option;
    } catch (const OpticsError& e) {
      EXPECT_EQ(e.option(), option);
      EXPECT_EQ(e.message(), message);
    }
  };
  expect_option([](Prescription& p) { set_corneal_cylinder(p, -1.0, 181.0); }, "axis",
                "181 deg is outside [0, 180] deg");
  expect_option([](Prescription& p) { set_corneal_cylinder(p, std::nan(""), 90.0); }, "cylinder",
                "nan D is outside [-20, 20] D");
  expect_option([](Prescription& p) { set_corneal_cylinder(p, 25.0, 0.0); }, "cylinder", "25 D is outside [-20, 20] D");
  expect_option([](Prescription& p) { set_pupil_decentration(p, 0.0, 3.5); }, "pupildecentration",
                "3.5 mm is outside [-3, 3] mm");
  expect_option(
      [](Prescription& p) {
        set_corneal_cylinder(p, -1.0, 10.0);
        set_corneal_cylinder(p, -1.0, 10.0);
      },
      "cylinder", "the first surface is not a rotationally symmetric refracting cornea");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
