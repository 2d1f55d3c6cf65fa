// The wavefront section of the optics report (report.h, `eyetrace optics --wave`): its keys, its
// numbers (those of trace_wavefront), a field the analysis cannot serve, bad options.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/psf.h"
#include "optics/report.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

Prescription navarro() {
  EyeOptions o;
  o.model = "navarro";
  return make_eye(o);
}

TEST(WavefrontReport, HasTheKeysAndTheNumbersOfTheAnalysis) {
  ReportOptions o;
  o.fields_deg = {0.0, 20.0};
  o.wave = true;
  o.wave_options.pupil_radius_mm = 3.0;
  const nlohmann::json r = optics_report(navarro(), o);
  ASSERT_TRUE(r.contains("wave"));
  ASSERT_EQ(r["wave"].size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& f = r["wave"][i];
    WavefrontOptions w = o.wave_options;
    w.field_deg = o.fields_deg[i];
    const WavefrontResult expected = trace_wavefront(navarro(), w);
    EXPECT_EQ(f["field_deg"].get<double>(), o.fields_deg[i]);
    EXPECT_EQ(f["wavelength_nm"].get<double>(), 589.3);
    EXPECT_NEAR(f["pupil_radius_mm"].get<double>(), 3.0, 1e-12);
    EXPECT_NEAR(f["rms_wavefront_waves"].get<double>(), expected.rms_waves, 1e-6);
    EXPECT_NEAR(f["pv_wavefront_waves"].get<double>(), expected.pv_waves, 1e-6);
    ASSERT_EQ(f["zernike_osa_um"].size(), 28u);
    for (size_t j = 0; j < 28; ++j) EXPECT_NEAR(f["zernike_osa_um"][j].get<double>(), expected.zernike_um[j], 1e-8);
    EXPECT_NEAR(f["refraction"]["least_squares"]["M_diopters"].get<double>(), expected.least_squares.M_D, 1e-6);
    EXPECT_NEAR(f["refraction"]["paraxial"]["J0_diopters"].get<double>(), expected.paraxial.J0_D, 1e-6);
    EXPECT_EQ(f["rays_lost"].get<int>(), 0);
    EXPECT_FALSE(f.contains("error"));
  }
  const std::string text = format_report(r);
  EXPECT_NE(text.find("wavefront (OPD against the sphere"), std::string::npos) << text;
  EXPECT_NE(text.find("field  20.0 deg, 589.3 nm, pupil 3.000 mm"), std::string::npos) << text;
  // Without the option the report has no wave section.
  EXPECT_FALSE(optics_report(navarro(), ReportOptions{}).contains("wave"));
}

// A field whose chief ray is vignetted keeps its entry: null numbers and the reason, no NaN.
TEST(WavefrontReport, ALostFieldIsReportedNotDropped) {
  ReportOptions o;
  o.fields_deg = {70.0};
  o.wave = true;
  const nlohmann::json r = optics_report(navarro(), o);
  const nlohmann::json& f = r["wave"][0];
  EXPECT_TRUE(f["rms_wavefront_waves"].is_null());
  EXPECT_TRUE(f["zernike_osa_um"].is_null());
  EXPECT_NE(f["error"].get<std::string>().find("chief ray lost"), std::string::npos) << f.dump();
  EXPECT_NE(format_report(r).find("chief ray lost"), std::string::npos);
}

// The diffraction keys are those of the library's PSF and MTF of the same wavefront traced with
// the real stop clipping (psf.h, mtf.h; tested against analytic answers in psf_test).
TEST(WavefrontReport, HasThePsfAndMtfOfTheAnalysis) {
  ReportOptions o;
  o.fields_deg = {0.0};
  o.wave = true;
  o.wave_options.wavelength_nm = 555.0;
  const nlohmann::json r = optics_report(navarro(), o);
  const nlohmann::json& f = r["wave"][0];
  WavefrontOptions w = o.wave_options;
  w.clip_at_stop = true;
  const WavefrontResult traced = trace_wavefront(navarro(), w);
  const Psf psf = compute_psf(traced, retinal_scale(navarro(), 0.0, o.object_distance_m, 555.0));
  EXPECT_NEAR(f["strehl"].get<double>(), psf.strehl, 1e-6);
  EXPECT_NEAR(f["ee50_um"].get<double>(), psf.ee50_um, 1e-6);
  EXPECT_NEAR(f["ee80_um"].get<double>(), psf.ee80_um, 1e-6);
  EXPECT_EQ(f["psf"]["rays_clipped"].get<int>(), traced.rays_lost);
  EXPECT_GT(traced.rays_lost, 0);  // the real stop trims the paraxial disc's rim
  const std::vector<MtfPoint> mtf = compute_mtf(psf, o.mtf_freqs_cpd);
  ASSERT_EQ(f["mtf"].size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(f["mtf"][i]["freq_cpd"].get<double>(), o.mtf_freqs_cpd[i]);
    EXPECT_NEAR(f["mtf"][i]["tangential"].get<double>(), mtf[i].tangential, 1e-6);
    EXPECT_NEAR(f["mtf"][i]["sagittal"].get<double>(), mtf[i].sagittal, 1e-6);
  }
  EXPECT_FALSE(f.contains("psf_warning")) << f.dump();
  const std::string text = format_report(r);
  EXPECT_NE(text.find("MTF cycles/deg"), std::string::npos) << text;
  EXPECT_NE(text.find(fmt::format("Strehl {:.4f}", psf.strehl)), std::string::npos) << text;
  // A frequency beyond the cut-off (D / lambda: the 4.531 mm paraxial pupil at 555 nm) is an error naming it.
  o.mtf_freqs_cpd = {10.0, 150.0};
  try {
    optics_report(navarro(), o);
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("cut-off 142.5 cycles/deg"), std::string::npos) << e.what();
  }
}

TEST(WavefrontReport, BadOptionsAreOneError) {
  ReportOptions o;
  o.wave = true;
  o.wave_options.grid = 2;
  EXPECT_THROW(optics_report(navarro(), o), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
