// Spot sizes and the optics report.
#include <cmath>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/report.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription navarro(double pupil_mm) {
  EyeOptions o;
  o.model = "navarro";
  o.pupil_diameter_mm = pupil_mm;
  return make_eye(o);
}

TEST(Spot, OnAxisRmsShrinksAsThePupilCloses) {
  double previous = 1e9;
  for (double pupil : {6.0, 5.0, 4.0, 3.0, 2.0, 1.0}) {
    const SpotResult s = trace_spot(navarro(pupil), {});
    ASSERT_GT(s.rays, 1000) << pupil;
    EXPECT_LT(s.rms_radius_um, previous) << pupil << " mm";
    previous = s.rms_radius_um;
  }
  EXPECT_LT(previous, 2.0);  // 1 mm pupil: geometric blur of a paraxially focused eye ~ 0
}

TEST(Spot, OnAxisSpotIsCentredAndUsesTheWholePupil) {
  const SpotResult s = trace_spot(navarro(4.0), {});
  EXPECT_NEAR(s.centroid_mm.x, 0.0, 1e-9);
  EXPECT_NEAR(s.centroid_mm.y, 0.0, 1e-9);
  // Rays kept / launched ~ area of the pupil disc / area of its bounding box (pi/4), less the
  // margin the bounding box gets.
  const double fraction = static_cast<double>(s.rays) / s.rays_launched;
  EXPECT_GT(fraction, 0.6);
  EXPECT_LT(fraction, 0.80);
}

TEST(Spot, OffAxisBlurGrowsWithField) {
  const Prescription p = navarro(4.0);
  double previous = 0.0;
  for (double field : {0.0, 20.0, 40.0}) {
    const SpotResult s = trace_spot(p, {field});
    ASSERT_GT(s.rays, 500);
    EXPECT_GT(s.rms_radius_um, previous);
    EXPECT_LT(s.centroid_mm.y, 0.0 + (field == 0.0 ? 1e-9 : 0.0));  // inverted image
    previous = s.rms_radius_um;
  }
  EXPECT_THROW(trace_spot(p, {90.0}), OpticsError);
}

TEST(Spot, NearObjectBlursARelaxedEye) {
  const Prescription p = navarro(4.0);
  const double far = trace_spot(p, {}).rms_radius_um;
  SpotOptions near;
  near.object_distance_m = 0.25;  // 4 D of defocus
  EXPECT_GT(trace_spot(p, near).rms_radius_um, 5 * far);
}

TEST(Report, HasTheDocumentedKeys) {
  const nlohmann::json r = optics_report(navarro(4.0));
  for (const char* key : {"power_diopters", "refraction_diopters", "axial_length_mm", "retina_radius_mm",
                          "principal_points_mm", "nodal_points_mm", "focal_lengths_mm", "entrance_pupil", "exit_pupil",
                          "spot", "model", "variant", "source", "wavelength_nm"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_NEAR(r["power_diopters"].get<double>(), 60.416, 0.001);
  EXPECT_NEAR(r["retina_radius_mm"].get<double>(), -12.0, 1e-9);
  EXPECT_NEAR(r["entrance_pupil"]["position_mm"].get<double>(), 3.0424, 1e-3);
  ASSERT_EQ(r["spot"].size(), 5u);
  EXPECT_EQ(r["spot"][4]["field_deg"].get<double>(), 40.0);
  EXPECT_GT(r["spot"][4]["rays"].get<int>(), 500);
  const std::string text = format_report(r);
  EXPECT_NE(text.find("power 60.416 D"), std::string::npos) << text;
  EXPECT_NE(text.find("field  40.0 deg"), std::string::npos) << text;

  EyeOptions o;
  o.model = "navarro";
  o.variant = "wu2011";
  EXPECT_TRUE(optics_report(make_eye(o))["retina_radius_mm"].is_null());
  // wu2011 is 1.24 D myopic (eye-models.md): far point -1 / refraction, about 0.8 m.
  const nlohmann::json wu = optics_report(make_eye(o));
  EXPECT_NEAR(wu["far_point_m"].get<double>(), -1.0 / wu["refraction_diopters"].get<double>(), 1e-5);
  EXPECT_NEAR(wu["far_point_m"].get<double>(), 0.81, 0.02);
}

// The relaxed Navarro eye is emmetropic (refraction 0 within 0.005 D, its published value):
// no far point, rather than the 98 km its rounded axial length implies.
TEST(Report, EmmetropicEyeHasNoFarPoint) {
  EyeOptions o;
  o.model = "navarro";
  const nlohmann::json r = optics_report(make_eye(o));
  EXPECT_NEAR(r["refraction_diopters"].get<double>(), 0.0, 0.005);
  EXPECT_TRUE(r["far_point_m"].is_null());
  o.accommodation_D = 1.0;  // the accommodated eye has a near far point
  EXPECT_FALSE(optics_report(make_eye(o))["far_point_m"].is_null());
}

TEST(Spot, Ee50RadiusHoldsHalfTheRays) {
  // Gullstrand's retina is flat, so the 2-D points are the distances the radius is taken over.
  EyeOptions o;
  o.model = "gullstrand";
  o.pupil_diameter_mm = 5.0;
  for (double field : {0.0, 20.0}) {
    const SpotResult s = trace_spot(make_eye(o), {field});
    ASSERT_GT(s.rays, 1000);
    const double r = s.ee50_radius_um;
    size_t inside = 0, strictly = 0;
    for (const glm::dvec2& q : s.points_um) {
      const double d = std::hypot(q.x, q.y);
      inside += d <= r * (1 + 1e-9);
      strictly += d < r * (1 - 1e-9);
    }
    const size_t half = (s.points_um.size() + 1) / 2;
    EXPECT_GE(inside, half) << field;
    EXPECT_LT(strictly, half) << field;
    // Markov's inequality on r^2: at most half the rays lie beyond sqrt(2) x the RMS radius.
    EXPECT_LE(r, std::sqrt(2.0) * s.rms_radius_um) << field;
  }
}

TEST(SpotDiagram, RasterHasPointsAndScaleBar) {
  const Prescription p = navarro(4.0);
  std::vector<SpotResult> spots{trace_spot(p, {0.0}), trace_spot(p, {20.0})};
  const RgbImage img = spot_diagram(spots, 400, 200);
  ASSERT_EQ(img.rgb.size(), 400u * 200u * 3u);
  EXPECT_GT(img.um_per_pixel, 0.0);
  EXPECT_GT(img.scale_bar_um, 0.0);
  int coloured = 0, black = 0;
  for (size_t i = 0; i < img.rgb.size(); i += 3) {
    const auto r = img.rgb[i], g = img.rgb[i + 1], b = img.rgb[i + 2];
    coloured += (r != g || g != b);
    black += (r == 0 && g == 0 && b == 0);
  }
  EXPECT_GT(coloured, 50);
  EXPECT_GT(black, 10);
  EXPECT_THROW(spot_diagram({}, 400, 200), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
