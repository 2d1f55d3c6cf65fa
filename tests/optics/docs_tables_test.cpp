// Keeps docs/eye-models.md honest: its generated tables must equal what the code computes now.
// On a mismatch the test prints the fresh tables; paste them between the markers in the doc.
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/eye_models_doc.h"
#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/paraxial.h"
#include "optics/spot.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

std::string preset_table() {
  std::string out =
      "| preset | power D | refraction D | axial length | F | F′ | H | H′ | N | N′ | entrance pupil (×) | exit pupil "
      "(×) | retina R | RMS spot µm at 0/10/20/30/40° |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const test::EyePreset& preset : test::kDocPresets) {
    const Prescription p = test::make_preset_eye(preset);
    const ParaxialData d = paraxial_analysis(p);
    std::string spots;
    for (double f : {0.0, 10.0, 20.0, 30.0, 40.0})
      spots += (spots.empty() ? "" : " / ") + fmt::format("{:.1f}", trace_spot(p, {f}).rms_radius_um);
    const Surface& retina = p.surfaces.back();
    out += fmt::format(
        "| {} | {:.3f} | {:+.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} (×{:.3f}) | "
        "{:.3f} (×{:.3f}) | {} | {} |\n",
        test::preset_label(preset), d.power_D, d.refraction_D + 0.0, d.axial_length_mm, d.front_focal_point_mm,
        d.back_focal_point_mm, d.front_principal_point_mm, d.back_principal_point_mm, d.front_nodal_point_mm,
        d.back_nodal_point_mm, d.entrance_pupil.position_mm, d.entrance_pupil.magnification, d.exit_pupil.position_mm,
        d.exit_pupil.magnification,
        retina.profile.is_flat() ? std::string("flat") : fmt::format("{:.1f}", 1.0 / retina.profile.curvature), spots);
  }
  return out;
}

std::string accommodation_table() {
  std::string out =
      "| D | navarro power D | navarro refraction D | wu2011 refraction D | gullstrand A → refraction | legrand A → "
      "refraction | arizona A → refraction |\n"
      "|---|---|---|---|---|---|---|\n";
  auto refraction = [](const char* model, const char* variant, double a) {
    EyeOptions o;
    o.model = model;
    o.variant = variant;
    o.accommodation_D = a;
    return paraxial_analysis(make_eye(o));
  };
  for (double D : {0.0, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0}) {
    const ParaxialData n = refraction("navarro", "", D);
    auto cell = [&](const char* model) {
      return D <= max_accommodation_D(model) ? fmt::format("{:+.3f}", refraction(model, "", D).refraction_D + 0.0)
                                             : std::string("–");
    };
    out += fmt::format("| {} | {:.3f} | {:+.3f} | {:+.3f} | {} | {} | {} |\n", D, n.power_D, n.refraction_D + 0.0,
                       refraction("navarro", "wu2011", D).refraction_D, cell("gullstrand"), cell("legrand"),
                       cell("arizona"));
  }
  return out;
}

TEST(EyeModelsDoc, PresetTableIsCurrent) { EXPECT_TRUE(test::table_is_in_eye_models_doc(preset_table())); }

TEST(EyeModelsDoc, AccommodationTableIsCurrent) {
  EXPECT_TRUE(test::table_is_in_eye_models_doc(accommodation_table()));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
