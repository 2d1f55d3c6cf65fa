// Prescription validation messages, JSON round trip, and the embedded data files.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/embedded_data.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/phase_plate.h"
#include "optics/prescription_io.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

void expect_invalid(const Prescription& p, const std::string& message) {
  try {
    validate(p);
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const OpticsError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

// One file per model and variant: arizona, escudero-sanz, gullstrand, kooijman, legrand,
// navarro and navarro's wu2011 variant.
TEST(EyeDataFiles, AllEmbeddedFilesLoadAndValidate) {
  const auto& files = embedded::files();
  EXPECT_EQ(files.size(), 7u);
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    const Prescription p = prescription_from_json_text(text, name);
    EXPECT_FALSE(p.source.empty());
    EXPECT_EQ(p.surfaces.back().role, SurfaceRole::Image);
    EXPECT_EQ(p.surfaces[p.stop_index()].name, "pupil");
  }
}

TEST(PrescriptionJson, RoundTripKeepsTheSystem) {
  const Prescription p = load_embedded_prescription("navarro.json");
  const Prescription q = prescription_from_json(prescription_to_json(p), "round trip");
  ASSERT_EQ(p.surfaces.size(), q.surfaces.size());
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    EXPECT_EQ(p.surfaces[i].name, q.surfaces[i].name);
    EXPECT_DOUBLE_EQ(p.surfaces[i].profile.curvature, q.surfaces[i].profile.curvature);
    EXPECT_DOUBLE_EQ(p.surfaces[i].profile.conic, q.surfaces[i].profile.conic);
    EXPECT_DOUBLE_EQ(p.surfaces[i].thickness_mm, q.surfaces[i].thickness_mm);
    EXPECT_DOUBLE_EQ(p.surfaces[i].index_after, q.surfaces[i].index_after);
  }
  EXPECT_DOUBLE_EQ(refraction_D(p), refraction_D(q));
}

TEST(PrescriptionJson, StrictAboutKeysAndTypes) {
  nlohmann::json j = prescription_to_json(load_embedded_prescription("legrand.json"));
  j["surfaces"][3]["radius"] = 5.0;
  try {
    prescription_from_json(j, "bad.json");
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_EQ(std::string(e.what()), "bad.json: surface 3: unknown key 'radius'");
  }
  j = prescription_to_json(load_embedded_prescription("legrand.json"));
  j["surfaces"][1]["medium"] = "aqueus";
  try {
    prescription_from_json(j, "bad.json");
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.json: surface 1 'cornea posterior': medium 'aqueus' is not in the media table");
  }
  EXPECT_THROW(prescription_from_json_text("{ not json", "x.json"), OpticsError);
}

TEST(PrescriptionValidation, MessagesNameSurfaceAndParameter) {
  const Prescription base = load_embedded_prescription("navarro.json");
  Prescription p = base;
  p.surfaces[3].semi_diameter_mm = 6.2;
  p.surfaces[3].profile = SurfaceProfile::from_radius(10.2, 5.0);  // oblate: reach 10.2/sqrt(6)
  expect_invalid(p, "surface 3 'lens anterior': semi-diameter 6.2 mm is beyond the conic's reach (max 4.16413 mm)");
  p = base;
  p.surfaces[1].thickness_mm = -0.1;
  expect_invalid(p, "surface 1 'cornea posterior': thickness -0.1 mm is negative");
  p = base;
  p.surfaces[4].profile.conic = std::nan("");
  expect_invalid(p, "surface 4 'lens posterior': conic is not a finite number (nan)");
  p = base;
  p.surfaces[2].role = SurfaceRole::Refract;
  expect_invalid(p, "prescription 'navarro': needs exactly one aperture stop (role 'stop'), found 0");
  p = base;
  p.surfaces[3].thickness_mm = 0.5;  // lens anterior and posterior cross
  try {
    validate(p);
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("surface 3 'lens anterior' and surface 4 'lens posterior' cross at height"),
              std::string::npos)
        << e.what();
  }
  p = base;
  p.surfaces[2].semi_diameter_mm = 0.0;
  expect_invalid(p, "surface 2 'pupil': the aperture stop needs a finite semi-diameter > 0 (got 0)");
  p = base;
  std::swap(p.surfaces[4], p.surfaces[5]);
  expect_invalid(p, "surface 4 'retina': only the last surface may have role 'image'");
}

// The optional fields of a non-symmetric surface (prescription_io.h): read, written back, and
// rejected with the file, surface and field named.
TEST(PrescriptionJson, BiconicAndPlacementFieldsRoundTrip) {
  nlohmann::json j = prescription_to_json(load_embedded_prescription("navarro.json"));
  j["surfaces"][0]["cross_radius_mm"] = 7.5;
  j["surfaces"][0]["cross_conic"] = -0.1;
  j["surfaces"][0]["axis_deg"] = 90.0;
  j["surfaces"][2]["decentre_mm"] = {0.3, -0.1};
  j["surfaces"][4]["tilt_deg"] = {1.5, -2.0};
  const Prescription p = prescription_from_json(j, "toric.json");
  const SurfaceProfile& c = p.surfaces[0].profile;
  EXPECT_EQ(c.kind, ProfileKind::Biconic);
  EXPECT_DOUBLE_EQ(c.curvature, 1.0 / 7.72);
  EXPECT_DOUBLE_EQ(c.conic, -0.26);
  EXPECT_DOUBLE_EQ(c.cross_curvature, 1.0 / 7.5);
  EXPECT_DOUBLE_EQ(c.cross_conic, -0.1);
  EXPECT_DOUBLE_EQ(c.axis_deg, 90.0);
  EXPECT_DOUBLE_EQ(p.surfaces[2].placement.decentre_x_mm, 0.3);
  EXPECT_DOUBLE_EQ(p.surfaces[2].placement.decentre_y_mm, -0.1);
  EXPECT_DOUBLE_EQ(p.surfaces[4].placement.tilt_x_deg, 1.5);
  EXPECT_DOUBLE_EQ(p.surfaces[4].placement.tilt_y_deg, -2.0);
  EXPECT_FALSE(p.rotationally_symmetric());
  EXPECT_NE(describe(p).find("biconic: cross radius 7.5"), std::string::npos) << describe(p);
  const Prescription q = prescription_from_json(prescription_to_json(p), "again");
  EXPECT_EQ(prescription_to_json(q), prescription_to_json(p));
  // A symmetric prescription writes none of the new keys.
  const nlohmann::json plain = prescription_to_json(load_embedded_prescription("navarro.json"));
  for (const auto& s : plain["surfaces"])
    for (const char* key : {"cross_radius_mm", "cross_conic", "axis_deg", "decentre_mm", "tilt_deg"})
      EXPECT_FALSE(s.contains(key)) << key;
}

// A phase plate (phase_plate.h) is written with the iris and read back as the same plate: the
// same JSON again and the same wavefront at a point; a bad coefficient list names the field.
TEST(PrescriptionJson, PhasePlateRoundTrips) {
  Prescription p = load_embedded_prescription("navarro.json");
  ZernikeFile f;
  f.origin = "eye.zer";
  f.pupil_diameter_mm = 5.0;
  f.wavelength_nm = 555.0;
  f.max_order = 4;
  f.coefficients_um = {0, 0.01, -0.02, 0.1, 0.3, -0.2, 0.05, 0.04, -0.03, 0.02, 0, 0.01, 0.12, 0, -0.01};
  add_phase_plate(p, f);
  const nlohmann::json j = prescription_to_json(p);
  const Prescription q = prescription_from_json(j, "again");
  EXPECT_EQ(prescription_to_json(q), j);
  const PhasePlate& a = *p.surfaces[p.stop_index()].phase_plate;
  const PhasePlate& b = *q.surfaces[q.stop_index()].phase_plate;
  EXPECT_EQ(b.wavefront_mm(0.7, -1.1), a.wavefront_mm(0.7, -1.1));
  EXPECT_EQ(b.origin, "eye.zer");

  nlohmann::json bad = j;
  bad["surfaces"][p.stop_index()]["phase_plate"]["zernike_osa_um"] = "0.1";
  try {
    prescription_from_json(bad, "bad.json");
    FAIL() << "no error";
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("phase_plate: 'zernike_osa_um'"), std::string::npos) << e.what();
  }
}

TEST(PrescriptionJson, BiconicAndPlacementErrorsNameTheField) {
  auto expect_error = [](const std::function<void(nlohmann::json&)>& edit, const std::string& message) {
    nlohmann::json j = prescription_to_json(load_embedded_prescription("navarro.json"));
    edit(j);
    try {
      prescription_from_json(j, "bad.json");
      ADD_FAILURE() << "no error; expected: " << message;
    } catch (const OpticsError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  expect_error(
      [](nlohmann::json& j) {
        j["surfaces"][0]["cross_radius_mm"] = 7.5;
        j["surfaces"][0]["axis_deg"] = 200.0;
      },
      "bad.json: surface 0 'cornea anterior': axis_deg 200 is outside [0, 180)");
  expect_error([](nlohmann::json& j) { j["surfaces"][0]["axis_deg"] = 90.0; },
               "bad.json: surface 0 'cornea anterior': 'axis_deg' needs 'cross_radius_mm' (a biconic)");
  expect_error([](nlohmann::json& j) { j["surfaces"][0]["cross_radius_mm"] = 0.0; },
               "bad.json: surface 0 'cornea anterior': cross_radius_mm 0 is not a radius (use null for flat)");
  expect_error([](nlohmann::json& j) { j["surfaces"][2]["decentre_mm"] = 0.3; },
               "bad.json: surface 2 'pupil': 'decentre_mm' must be a list of two numbers [x, y]");
  expect_error(
      [](nlohmann::json& j) {
        j["surfaces"][4]["tilt_deg"] = {85.0, 0.0};
      },
      "bad.json: surface 4 'lens posterior': tilt 85 deg is outside (-80, 80) deg");
  expect_error(
      [](nlohmann::json& j) {
        j["surfaces"][4]["decentre_mm"] = {2000.0, 0.0};
      },
      "bad.json: surface 4 'lens posterior': decentration 2000 mm is beyond +-1000 mm");
  // A tilt that makes the lens's front face cut through the iris plane.
  expect_error(
      [](nlohmann::json& j) {
        j["surfaces"][3]["tilt_deg"] = {0.0, 5.0};
      },
      "bad.json: surface 2 'pupil' and surface 3 'lens anterior' cross at (0.03125, 0) mm, inside their "
      "clear apertures: thickness 0 mm is too small for their sags, tilts and decentrations");
}

TEST(MeetingHeight, GullstrandAccommodatedNucleusEdge) {
  // Two spherical caps R = +-2.655 with vertices 2.655 apart meet where
  // 2.655 - sqrt(R^2 - h^2) = sqrt(R^2 - h^2) - 0, i.e. h = R sqrt(3)/2 = 2.2993 mm.
  const double R = 2.655;
  const double h = meeting_height(SurfaceProfile::from_radius(R, 0), 0.0, SurfaceProfile::from_radius(-R, 0), R, R);
  EXPECT_NEAR(h, R * std::sqrt(3.0) / 2.0, 1e-9);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
