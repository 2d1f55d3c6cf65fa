// Refractive ametropia: the anterior corneal radius is solved so the eye's refraction is the one
// asked for. Checked against the independent y-nu refraction of tests/support (not the solver's
// vergence identity), and against what must not change: the axial length and the cornea's conic
// stay the model's, while the axial ametropia keeps the cornea and changes the length.
#include <gtest/gtest.h>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/refractive_ametropia.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription eye(const char* model, double error_D, Ametropia kind, double accommodation_D = 0.0) {
  EyeOptions o;
  o.model = model;
  o.refractive_error_D = error_D;
  o.ametropia = kind;
  o.accommodation_D = accommodation_D;
  return make_eye(o);
}

TEST(RefractiveAmetropia, CornealRadiusGivesTheRefractionAndKeepsTheLength) {
  for (const char* model : {"navarro", "legrand", "gullstrand", "arizona"}) {
    const Prescription plain = eye(model, 0.0, Ametropia::Axial);
    for (const double error_D : {-6.0, -3.0, 2.0, 5.0}) {
      const Prescription refractive = eye(model, error_D, Ametropia::Refractive);
      const Prescription axial = eye(model, error_D, Ametropia::Axial);
      const double c0 = plain.surfaces[0].profile.curvature;
      EXPECT_NEAR(test::meridian_refraction(refractive, refractive.surfaces[0].profile.curvature), error_D, 1e-9)
          << model << " " << error_D;
      EXPECT_NEAR(test::meridian_refraction(axial, axial.surfaces[0].profile.curvature), error_D, 1e-9) << model;
      EXPECT_DOUBLE_EQ(refractive.axial_length_mm(), plain.axial_length_mm()) << model;
      EXPECT_EQ(refractive.surfaces[0].profile.conic, plain.surfaces[0].profile.conic) << model;
      // A myope's cornea is steeper (more power), a hyperope's flatter: (n' - 1) dc = -dR, from the
      // model's own refraction (not exactly 0: e.g. Arizona's is +0.007 D).
      const double n = plain.surfaces[0].index_after, r0 = test::meridian_refraction(plain, c0);
      EXPECT_NEAR(1000.0 * (n - 1.0) * (refractive.surfaces[0].profile.curvature - c0), r0 - error_D, 1e-9) << model;
      EXPECT_EQ(axial.surfaces[0].profile.curvature, c0) << model;
      EXPECT_EQ(axial.axial_length_mm() > plain.axial_length_mm(), error_D < 0.0) << model;
    }
  }
}

TEST(RefractiveAmetropia, AccommodatedEyeKeepsTheSolvedCornea) {
  const Prescription relaxed = eye("navarro", -3.0, Ametropia::Refractive);
  const Prescription near = eye("navarro", -3.0, Ametropia::Refractive, 4.0);
  EXPECT_EQ(near.surfaces[0].profile.curvature, relaxed.surfaces[0].profile.curvature);
  EXPECT_LT(test::meridian_refraction(near, near.surfaces[0].profile.curvature), -3.0 - 1.0);
}

TEST(RefractiveAmetropia, PowerBeyondAConvexCorneaNamesRefractiveError) {
  // -30 D needs a cornea of about 79 D (radius 4.8 mm), which meets the posterior cornea inside
  // its clear aperture: refused, naming the option.
  try {
    eye("navarro", -30.0, Ametropia::Refractive);
    FAIL() << "no error";
  } catch (const OpticsError& e) {
    EXPECT_EQ(e.option(), "refractiveerror") << e.what();
  }
  Prescription p = eye("navarro", 0.0, Ametropia::Axial);
  const Prescription relaxed = p;
  try {
    set_refraction_by_cornea(p, relaxed, 60.0);  // a cornea of negative power
    FAIL() << "no error";
  } catch (const OpticsError& e) {
    EXPECT_EQ(e.option(), "refractiveerror");
    EXPECT_NE(e.message().find("60 D"), std::string::npos) << e.message();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
