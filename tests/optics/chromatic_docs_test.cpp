// Keeps the chromatic table of docs/eye-models.md honest: it must equal what the code computes
// now. On a mismatch the test prints the fresh table; paste it over the old one in the doc.
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/eye_models_doc.h"
#include "../support/unity_id.h"
#include "optics/chromatic.h"
#include "optics/eye_models.h"
#include "optics/paraxial.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// Rounded first, so -0.0004 prints as +0.000.
std::string signed3(double v) { return fmt::format("{:+.3f}", std::round(v * 1000.0) / 1000.0 + 0.0); }

std::string chromatic_table() {
  std::string out =
      "| preset | dispersion | refraction D at 400 / ref / 700 nm | LCA 400–700 nm D | TCA 450–650 nm arcmin at "
      "10 / 20 / 30° | at 20°: retina µm, spot-centroid TCA arcmin |\n"
      "|---|---|---|---|---|---|\n";
  for (const test::EyePreset& preset : test::kDocPresets) {
    const Prescription p = test::make_preset_eye(preset);
    const auto curve = chromatic_refraction(p, {});
    std::string tca;
    TransverseChromatic at20;
    for (double field : {10.0, 20.0, 30.0}) {
      const TransverseChromatic t =
          transverse_chromatic_aberration(p, field, std::numeric_limits<double>::infinity(), {});
      tca += (tca.empty() ? "" : " / ") + fmt::format("{:+.2f}", t.tca_arcmin);
      if (field == 20.0) at20 = t;
    }
    out += fmt::format("| {} | {}{} | {} / {} ({:g}) / {} | {:.3f} | {} | {:+.1f}, {:+.2f} |\n",
                       test::preset_label(preset), to_string(p.media.front().dispersion.law),
                       p.dispersion_assumed ? ", **assumed**" : "", signed3(curve.front().refraction_D),
                       signed3(refraction_D(p)), p.reference_wavelength_nm, signed3(curve.back().refraction_D),
                       curve.back().refraction_D - curve.front().refraction_D, tca, at20.retina_um,
                       at20.centroid_tca_arcmin);
  }
  return out;
}

TEST(EyeModelsDoc, ChromaticTableIsCurrent) { EXPECT_TRUE(test::table_is_in_eye_models_doc(chromatic_table())); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
