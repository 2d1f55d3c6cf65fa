// `eyetrace optics`: the chromatic section of the report (JSON and text), its options and their
// errors, and the --plot figure (spot diagram above the chromatic refraction curve).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/eyetrace_process.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "optics/prescription_io.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::run_eyetrace;

TEST(OpticsCommand, ChromaticJson) {
  const test::RunResult run = run_eyetrace("optics --json --camera 'Camera \"kooijman\"'", false);
  ASSERT_EQ(run.status, 0);
  const nlohmann::json r = nlohmann::json::parse(run.output);
  ASSERT_EQ(r["chromatic_refraction"].size(), 31u);
  EXPECT_EQ(r["chromatic_refraction"][0]["wavelength_nm"].get<double>(), 400.0);
  EXPECT_TRUE(r["chromatic_refraction"][0].contains("refraction_diopters"));
  EXPECT_TRUE(r["dispersion"]["assumed"].get<bool>());  // Kooijman publishes none
  EXPECT_EQ(r["dispersion"]["media"][0]["law"].get<std::string>(), "cornu");
  ASSERT_EQ(r["tca"]["fields"].size(), 5u);
  for (const auto& f : r["tca"]["fields"]) EXPECT_TRUE(f["tca_arcmin"].is_number()) << f.dump();

  const test::RunResult run_narrow = run_eyetrace(
      "optics --json --chromatic-range 450,650 --chromatic-step 50 --tca-wavelengths 470,620 --fields 20", false);
  ASSERT_EQ(run_narrow.status, 0);
  const nlohmann::json narrow = nlohmann::json::parse(run_narrow.output);
  ASSERT_EQ(narrow["chromatic_refraction"].size(), 5u);
  EXPECT_EQ(narrow["chromatic_refraction"][4]["wavelength_nm"].get<double>(), 650.0);
  EXPECT_EQ(narrow["tca"]["short_wavelength_nm"].get<double>(), 470.0);
  EXPECT_EQ(narrow["tca"]["fields"].size(), 1u);
}

// "string zernikefile" on the camera: the report lists the plate (JSON and text) and the wave
// report's least-squares refraction moves by the file's c(2,0) = 0.25 um over its 6 mm pupil,
// M = -4 sqrt(3) c / r^2 = -0.192 D (Thibos et al. 2004; optics/phase_plate_test.cpp for the
// 1 % the pupil mapping leaves), J0 by c(2,2) = 0.12 um, -2 sqrt(6) c / r^2 = -0.065 D.
TEST(OpticsCommand, ZernikeFileOnTheCamera) {
  const std::string file = std::string(EYETRACE_SOURCE_DIR) + "/scenes/measured-eye.zer";
  const std::string eye = "Camera \"navarro\" \"float pupildiameter\" 5.3";
  const std::string args = "optics --json --wave --wave-pupil 6 --fields 0 --camera ";
  const test::RunResult plain = run_eyetrace(args + "'" + eye + "'", false);
  const test::RunResult measured = run_eyetrace(args + "'" + eye + " \"string zernikefile\" \"" + file + "\"'", false);
  ASSERT_EQ(plain.status, 0) << plain.output;
  ASSERT_EQ(measured.status, 0) << measured.output;
  const nlohmann::json a = nlohmann::json::parse(plain.output), b = nlohmann::json::parse(measured.output);
  const nlohmann::json& iris = b["surfaces"][2];  // Navarro's stop, "pupil"
  ASSERT_EQ(iris["role"].get<std::string>(), "stop");
  ASSERT_TRUE(iris.contains("phase_plate")) << b["surfaces"].dump();
  EXPECT_EQ(iris["phase_plate"]["zernike_osa_um"][12].get<double>(), 0.10);
  EXPECT_EQ(iris["phase_plate"]["measured_pupil_diameter_mm"].get<double>(), 6.0);
  const nlohmann::json &ra = a["wave"][0]["refraction"]["least_squares"],
                       &rb = b["wave"][0]["refraction"]["least_squares"];
  EXPECT_NEAR(rb["M_diopters"].get<double>() - ra["M_diopters"].get<double>(), -4 * std::sqrt(3.0) * 0.25 / 9, 0.01);
  EXPECT_NEAR(rb["J0_diopters"].get<double>() - ra["J0_diopters"].get<double>(), -2 * std::sqrt(6.0) * 0.12 / 9, 0.01);
  EXPECT_NEAR(rb["J45_diopters"].get<double>() - ra["J45_diopters"].get<double>(), 2 * std::sqrt(6.0) * 0.08 / 9, 0.01);

  const test::RunResult text = run_eyetrace("optics --camera '" + eye + " \"string zernikefile\" \"" + file + "\"'");
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("phase plate on surface 2 'pupil': " + file), std::string::npos) << text.output;

  const test::RunResult bad = run_eyetrace("optics --camera 'Camera \"navarro\" \"string zernikefile\" \"no.zer\"'");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("parameter \"zernikefile\""), std::string::npos) << bad.output;
}

TEST(OpticsCommand, ChromaticText) {
  const test::RunResult run = run_eyetrace("optics --camera 'Camera \"gullstrand\"'");
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string& text = run.output;
  EXPECT_NE(text.find("dispersion (assumed"), std::string::npos) << text;
  EXPECT_NE(text.find("chromatic difference of refraction, 400-700 nm every 10 nm"), std::string::npos) << text;
  EXPECT_NE(text.find("transverse chromatic aberration 450-650 nm"), std::string::npos) << text;
}

TEST(OpticsCommand, WaveJsonAndText) {
  const test::RunResult json_run =
      run_eyetrace("optics --json --wave --wave-pupil 6 --fields 0,20 --camera 'Camera \"navarro\"'", false);
  ASSERT_EQ(json_run.status, 0);
  const nlohmann::json r = nlohmann::json::parse(json_run.output);
  ASSERT_EQ(r["wave"].size(), 2u);
  for (const auto& f : r["wave"]) {
    for (const char* key : {"field_deg", "wavelength_nm", "rms_wavefront_waves", "pv_wavefront_waves"})
      EXPECT_TRUE(f[key].is_number()) << key << " " << f.dump();
    EXPECT_EQ(f["zernike_osa_um"].size(), 28u);
    EXPECT_NEAR(f["pupil_radius_mm"].get<double>(), 3.0, 1e-12);
    EXPECT_TRUE(f["refraction"]["paraxial"]["M_diopters"].is_number());
    for (const char* key : {"strehl", "ee50_um", "ee80_um"}) EXPECT_TRUE(f[key].is_number()) << key << " " << f.dump();
    ASSERT_EQ(f["mtf"].size(), 6u);  // the default frequencies 5, 10, 20, 30, 40, 60
    EXPECT_EQ(f["mtf"][5]["freq_cpd"].get<double>(), 60.0);
    for (const auto& m : f["mtf"]) EXPECT_TRUE(m["tangential"].is_number() && m["sagittal"].is_number()) << m.dump();
  }
  EXPECT_NEAR(r["wave"][0]["zernike_osa_um"][12].get<double>(), 0.2406, 1e-4);  // docs/wavefront.md
  const test::RunResult text = run_eyetrace("optics --wave --fields 0");
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("wavefront (OPD against the sphere"), std::string::npos) << text.output;
}

TEST(OpticsCommand, WaveFreqsAreTheMtfFrequencies) {
  const test::RunResult run = run_eyetrace("optics --json --wave --fields 0 --freqs 10,30", false);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json f = nlohmann::json::parse(run.output)["wave"][0];
  ASSERT_EQ(f["mtf"].size(), 2u);
  EXPECT_EQ(f["mtf"][1]["freq_cpd"].get<double>(), 30.0);
  for (const char* bad : {"--freqs 10,500", "--freqs 10,x", "--freqs -5"}) {
    const test::RunResult out = run_eyetrace(std::string("optics --wave --fields 0 ") + bad);
    EXPECT_EQ(out.status, 1) << out.output;
    EXPECT_NE(out.output.find("--freqs"), std::string::npos) << out.output;
  }
  EXPECT_NE(run_eyetrace("optics --wave --fields 0 --freqs 500").output.find("diffraction cut-off"), std::string::npos);
}

TEST(OpticsCommand, BadWaveOptionsNameTheFlag) {
  for (const char* flag : {"--wave-grid 4", "--zernike-order 1", "--wave-pupil -1", "--wave-wavelength 200"}) {
    const test::RunResult out = run_eyetrace(std::string("optics --wave ") + flag);
    EXPECT_EQ(out.status, 1) << out.output;
    const std::string name(flag, std::string(flag).find(' '));
    EXPECT_NE(out.output.find(name), std::string::npos) << out.output;
  }
}

// --polychromatic adds the V(lambda)-weighted PSF's numbers under each field's wave entry (their
// values are tested in tests/optics/polychromatic_psf_test.cpp); a narrow range keeps it quick.
TEST(OpticsCommand, PolychromaticJsonAndText) {
  const test::RunResult run = run_eyetrace(
      "optics --json --wave --polychromatic --poly-range 500,600 --poly-step 25 --fields 0 --freqs 10,30", false);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json f = nlohmann::json::parse(run.output)["wave"][0];
  ASSERT_TRUE(f.contains("polychromatic")) << f.dump();
  const nlohmann::json& poly = f["polychromatic"];
  EXPECT_EQ(poly["wavelengths_nm"]["count"].get<int>(), 5);
  EXPECT_EQ(poly["source"].get<std::string>(), "equal-energy");
  for (const char* key : {"strehl", "ee50_um", "ee80_um"}) EXPECT_TRUE(poly[key].is_number()) << key;
  EXPECT_GT(poly["strehl"].get<double>(), 0.0);
  EXPECT_LE(poly["strehl"].get<double>(), 1.0);
  ASSERT_EQ(poly["mtf"].size(), 2u);
  EXPECT_EQ(poly["mtf"][1]["freq_cpd"].get<double>(), 30.0);
  EXPECT_LE(poly["mtf"][1]["tangential"].get<double>(), poly["mtf"][1]["diffraction_limit"][1].get<double>());

  const test::RunResult hot = run_eyetrace(
      "optics --json --wave --polychromatic --poly-range 500,600 --poly-step 50 --poly-source blackbody:3000 --fields "
      "0",
      false);
  ASSERT_EQ(hot.status, 0) << hot.output;
  EXPECT_EQ(nlohmann::json::parse(hot.output)["wave"][0]["polychromatic"]["source"].get<std::string>(),
            "blackbody 3000 K");
  const test::RunResult text =
      run_eyetrace("optics --wave --polychromatic --poly-range 540,580 --poly-step 20 --fields 0");
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("polychromatic (540-580 nm every 20 nm, V(lambda) x equal-energy source): Strehl"),
            std::string::npos)
      << text.output;
  // Without it there is no polychromatic object.
  const test::RunResult plain = run_eyetrace("optics --json --wave --fields 0", false);
  EXPECT_FALSE(nlohmann::json::parse(plain.output)["wave"][0].contains("polychromatic"));
}

TEST(OpticsCommand, BadPolychromaticOptionsNameTheFlag) {
  const std::pair<const char*, const char*> cases[] = {
      {"--wave --polychromatic --poly-range 350,700", "--poly-range \"350,700\": polychromatic range"},
      {"--wave --polychromatic --poly-range 400", "--poly-range \"400\": expected two wavelengths"},
      {"--wave --polychromatic --poly-step 0", "--poly-step \"0\": polychromatic step"},
      {"--wave --polychromatic --poly-step x", "--poly-step \"x\": expected a step"},
      {"--wave --polychromatic --poly-source sun", "--poly-source \"sun\""},
      {"--wave --polychromatic --poly-source blackbody:1", "--poly-source \"blackbody:1\""},
      {"--polychromatic", "--polychromatic: give --wave too"},
  };
  for (auto [args, expected] : cases) {
    const test::RunResult run = run_eyetrace(std::string("optics --fields 0 ") + args);
    EXPECT_EQ(run.status, 1) << args;
    EXPECT_NE(run.output.find(expected), std::string::npos) << args << ": " << run.output;
  }
}

TEST(OpticsCommand, BadWavelengthsNameTheFlag) {
  const std::pair<const char*, const char*> cases[] = {
      {"--chromatic-range 300,700", "--chromatic-range \"300,700\": chromatic range: 300 nm is outside [360, 1020] nm"},
      {"--chromatic-range 400,1100", "--chromatic-range \"400,1100\": chromatic range: 1100 nm is outside"},
      {"--chromatic-range 700,400", "--chromatic-range \"700,400\""},
      {"--chromatic-range 400", "--chromatic-range \"400\": expected two wavelengths"},
      {"--chromatic-step 0", "--chromatic-step \"0\""},
      {"--chromatic-step x", "--chromatic-step \"x\""},
      {"--tca-wavelengths 450,1100", "--tca-wavelengths \"450,1100\": tca wavelengths: 1100 nm is outside"},
      {"--tca-wavelengths 650,450", "--tca-wavelengths \"650,450\""},
  };
  for (auto [args, expected] : cases) {
    const test::RunResult run = run_eyetrace(std::string("optics ") + args);
    EXPECT_EQ(run.status, 1) << args;
    EXPECT_NE(run.output.find(expected), std::string::npos) << args << ": " << run.output;
  }
}

TEST(OpticsCommand, PlotHasSpotsAndCurve) {
  const std::string dir = std::string(EYETRACE_BINARY_DIR) + "/tests/optics_command_test";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/navarro.png";
  std::filesystem::remove(path);
  const test::RunResult run = run_eyetrace("optics --fields 0,20 --plot " + path);
  ASSERT_EQ(run.status, 0) << run.output;
  const Image image = read_image(path);
  EXPECT_EQ(image.width, 720);         // the curve's width (two 256-pixel spot panels are narrower)
  EXPECT_EQ(image.height, 256 + 400);  // spot diagram above, curve below
  EXPECT_EQ(read_image_attribute(path, "eyetrace:spot_diagram_height"), "256");
  EXPECT_NEAR(std::stod(read_image_attribute(path, "eyetrace:lca_diopters")), 2.485, 0.001);
}

// --plot DIR: the spot figure and, with --wave, one figure per field (MTF curves beside the PSF).
TEST(OpticsCommand, PlotDirectoryHasAWaveFigurePerField) {
  const std::string dir = std::string(EYETRACE_BINARY_DIR) + "/tests/optics_command_test/wave_plots";
  std::filesystem::remove_all(dir);
  const test::RunResult run = run_eyetrace("optics --wave --fields 0,20 --freqs 10,30 --plot " + dir);
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* name : {"spots.png", "wave_field_0.png", "wave_field_20.png"})
    EXPECT_NE(run.output.find("figure written to " + dir + "/" + name), std::string::npos) << run.output;
  const Image image = read_image(dir + "/wave_field_20.png");
  EXPECT_EQ(image.width, 960);
  EXPECT_EQ(image.height, 440);
  EXPECT_EQ(read_image_attribute(dir + "/wave_field_20.png", "eyetrace:field_deg"), "20");
  EXPECT_EQ(read_image_attribute(dir + "/wave_field_0.png", "eyetrace:psf_scale"), "log");
  // The figure has the PSF panel's black background and the curves' colours, not a blank page.
  double dark = 0.0, total = 0.0;
  for (size_t i = 0; i < image.pixels.size(); i += 3) {
    dark += image.pixels[i] < 0.01f ? 1.0 : 0.0;
    total += 1.0;
  }
  EXPECT_GT(dark / total, 0.2);
  EXPECT_TRUE(read_image(dir + "/spots.png").width > 0);
}

TEST(OpticsCommand, BadPlotDirectoryIsAClearError) {
  const std::string dir = std::string(EYETRACE_BINARY_DIR) + "/tests/optics_command_test";
  std::filesystem::create_directories(dir);
  const std::string file = dir + "/not_a_directory";
  std::ofstream(file) << "x";
  const test::RunResult over_file = run_eyetrace("optics --wave --fields 0 --plot " + file);
  EXPECT_EQ(over_file.status, 1);
  EXPECT_NE(over_file.output.find("--plot \"" + file + "\": exists and is not a directory"), std::string::npos)
      << over_file.output;
  const test::RunResult under_file = run_eyetrace("optics --wave --fields 0 --plot " + file + "/figures");
  EXPECT_EQ(under_file.status, 1);
  EXPECT_NE(under_file.output.find("--plot \"" + file + "/figures\": cannot create the directory"), std::string::npos)
      << under_file.output;
  const test::RunResult scale = run_eyetrace("optics --wave --fields 0 --psf-scale sqrt --plot " + dir + "/x");
  EXPECT_EQ(scale.status, 1);
  EXPECT_NE(scale.output.find("--psf-scale \"sqrt\": expected log or linear"), std::string::npos) << scale.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x"));  // checked before anything is written
}

// The refraction as sphere, cylinder and axis and as a power vector (keys of issue 16): a -3 D
// axial myope has sphere -3 (the refractiveerror it was built with), no cylinder, M = -3.
TEST(OpticsCommand, SpheroCylinderKeys) {
  const test::RunResult run =
      run_eyetrace("optics --json --fields 0 --camera 'Camera \"navarro\" \"float refractiveerror\" -3'", false);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json r = nlohmann::json::parse(run.output);
  EXPECT_NEAR(r.at("sphere_diopters").get<double>(), -3.0, 1e-6);
  EXPECT_EQ(r.at("cylinder_diopters").get<double>(), 0.0);
  EXPECT_EQ(r.at("axis_deg").get<double>(), 0.0);
  EXPECT_NEAR(r.at("M").get<double>(), -3.0, 1e-6);
  EXPECT_EQ(r.at("J0").get<double>(), 0.0);
  EXPECT_EQ(r.at("J45").get<double>(), 0.0);
  const test::RunResult text =
      run_eyetrace("optics --fields 0 --camera 'Camera \"navarro\" \"float refractiveerror\" -3'");
  EXPECT_NE(text.output.find("refraction -3.000 / +0.000 x 0.0 (sphere D / minus cylinder D x axis deg)"),
            std::string::npos)
      << text.output;
}

// --prescription: a prescription JSON with a toric anterior cornea (1.50 D steeper in the 180
// meridian: (1.376 - 1)(1/R' - 1/7.72) = 1.5 D) reports -1.50 D of cylinder at axis 90 (the
// cornea lies in the refraction's reference plane, docs/eye-models.md); a bad field is an error
// naming the file, the surface and the field.
TEST(OpticsCommand, PrescriptionFileWithAToricCornea) {
  const test::TempDir dir("optics-prescription");
  nlohmann::json j = optics::prescription_to_json(optics::load_embedded_prescription("navarro.json"));
  j["surfaces"][0]["cross_radius_mm"] = 1.0 / (1.0 / 7.72 + 1.5e-3 / 0.376);
  j["surfaces"][0]["axis_deg"] = 90.0;
  const std::string path = dir.file("toric.json");
  std::ofstream(path) << j.dump(2);
  const test::RunResult run = run_eyetrace("optics --json --fields 0 --prescription " + path, false);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json r = nlohmann::json::parse(run.output);
  EXPECT_NEAR(r.at("cylinder_diopters").get<double>(), -1.5, 1e-6);
  EXPECT_NEAR(r.at("axis_deg").get<double>(), 90.0, 1e-6);
  EXPECT_NEAR(r.at("J0").get<double>(), -0.75, 1e-6);  // -C/2 cos(2 x 90 deg) = 0.75 x (-1)

  j["surfaces"][0]["axis_deg"] = 200.0;
  const std::string bad = dir.file("bad.json");
  std::ofstream(bad) << j.dump(2);
  const test::RunResult failed = run_eyetrace("optics --prescription " + bad);
  EXPECT_NE(failed.status, 0);
  EXPECT_NE(
      failed.output.find("--prescription: " + bad + ": surface 0 'cornea anterior': axis_deg 200 is outside [0, 180)"),
      std::string::npos)
      << failed.output;
  const test::RunResult both = run_eyetrace("optics --camera 'Camera \"navarro\"' --prescription " + path);
  EXPECT_NE(both.status, 0);
  EXPECT_NE(both.output.find("give --camera or --prescription, not both"), std::string::npos) << both.output;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
