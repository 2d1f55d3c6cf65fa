// The contact lens layer: its back-vertex power in air, from a y-nu trace written here through its
// front and the cornea it sits on (the lens's back), is the one asked for in each meridian of a
// spherical or astigmatic cornea; a -3.00 D lens corrects an eye of -3.00 D at the cornea within
// 0.05 D (independent refraction of tests/support); a plus lens keeps its edge; bad powers name
// the option.
#include <cmath>

#include <gtest/gtest.h>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "optics/contact_lens.h"
#include "optics/corneal_astigmatism.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/sphero_cylinder.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription myope(double refraction_D) {
  EyeOptions o;
  o.model = "navarro";
  o.refractive_error_D = refraction_D;
  return make_eye(o);
}

// The lens in air: front c1 (air -> n), thickness t, back c2 (n -> air).
double bvp_in_air(double n, double t, double c1, double c2) {
  const double nu1 = -(n - 1.0) * c1;
  const double y2 = 1.0 + t / n * nu1;
  return -1000.0 * (nu1 - (1.0 - n) * c2 * y2) / y2;
}

TEST(ContactLens, BackVertexPowerInAir) {
  for (const double power : {-10.0, -3.0, 2.0, 8.0}) {
    Prescription p = myope(0.0);
    const SurfaceProfile cornea = p.surfaces[0].profile;
    add_contact_lens(p, power);
    ASSERT_EQ(p.surfaces[1].profile.curvature, cornea.curvature);  // the cornea is the lens's back
    EXPECT_EQ(p.surfaces[0].index_after, kContactLensIndex);
    EXPECT_NEAR(
        bvp_in_air(kContactLensIndex, p.surfaces[0].thickness_mm, p.surfaces[0].profile.curvature, cornea.curvature),
        power, 1e-9);
    EXPECT_EQ(p.surfaces[0].profile.conic, cornea.conic);
    if (power < 0) EXPECT_EQ(p.surfaces[0].thickness_mm, kContactLensThickness_mm);
  }
  // On an astigmatic cornea, in each principal meridian.
  Prescription p = myope(0.0);
  set_corneal_cylinder(p, -2.0, 45.0);
  const SurfaceProfile cornea = p.surfaces[0].profile;
  add_contact_lens(p, -4.0);
  const SurfaceProfile& front = p.surfaces[0].profile;
  ASSERT_EQ(front.kind, ProfileKind::Biconic);
  EXPECT_EQ(front.axis_deg, cornea.axis_deg);
  const double t = p.surfaces[0].thickness_mm;
  EXPECT_NEAR(bvp_in_air(kContactLensIndex, t, front.curvature, cornea.curvature), -4.0, 1e-9);
  EXPECT_NEAR(bvp_in_air(kContactLensIndex, t, front.cross_curvature, cornea.cross_curvature), -4.0, 1e-9);
}

TEST(ContactLens, CorrectsAMyopeAtTheCornea) {
  for (const double refraction : {-3.0, -6.0, 3.0}) {
    Prescription p = myope(refraction);
    add_contact_lens(p, refraction);
    EXPECT_NEAR(test::meridian_refraction_at(p, 0.0), 0.0, 0.05) << refraction;
    EXPECT_NEAR(refraction_sphero_cylinder(p).sphere_D, 0.0, 0.05) << refraction;
  }
}

TEST(ContactLens, PlusLensKeepsItsEdge) {
  Prescription p = myope(0.0);
  const double h = p.surfaces[0].semi_diameter_mm;
  add_contact_lens(p, 12.0);
  const double edge = p.surfaces[0].thickness_mm + p.surfaces[1].profile.sag(h * h) - p.surfaces[0].profile.sag(h * h);
  EXPECT_GE(edge, kMinContactLensEdge_mm - 1e-9);
  EXPECT_GT(p.surfaces[0].thickness_mm, kContactLensThickness_mm);
}

TEST(ContactLens, BadPowersNameContactLens) {
  for (const double power : {25.0, -21.0, std::nan("")}) {
    Prescription p = myope(0.0);
    try {
      add_contact_lens(p, power);
      FAIL() << power;
    } catch (const OpticsError& e) {
      EXPECT_EQ(e.option(), "contactlens");
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
