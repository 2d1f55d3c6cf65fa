// Chromatic aberration of the eye models (chromatic.h, the report's chromatic section), against
// an independent computation, closed-form cases and published numbers. Each tolerance says
// where it comes from.
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/unity_id.h"
#include "optics/chromatic.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/report.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

Prescription eye(const std::string& model, const std::string& variant = "", double accommodation = 0.0,
                 double pupil = 4.0) {
  EyeOptions o;
  o.model = model;
  o.variant = variant;
  o.accommodation_D = accommodation;
  o.pupil_diameter_mm = pupil;
  return make_eye(o);
}

double refraction_at(const Prescription& p, double lambda) { return refraction_D(at_wavelength(p, lambda)); }

// Refraction relative to 589.3 nm.
double relative(const Prescription& p, double lambda) { return refraction_at(p, lambda) - refraction_at(p, 589.3); }

const json& reference() {
  static const json j = [] {
    std::ifstream in(std::string(EYETRACE_SOURCE_DIR) + "/tests/data/optics/chromatic_reference.json");
    return json::parse(in);
  }();
  return j;
}

Prescription preset(const json& state) {
  const json& e = state["eyetrace_preset"];
  return eye(e["model"].get<std::string>(), e["variant"].get<std::string>(), e["accommodation_D"].get<double>());
}

// --- the independent computation (tools/chromatic_reference.py) -------------------------------

// Paraxial refraction at 31 wavelengths and the reference wavelength of 9 eye states (the
// accommodated Navarro and Arizona eyes too). 1e-6 D is the tolerance the issue asks for; both
// sides are closed-form matrix products, so they agree to rounding (about 1e-12 D).
TEST(ChromaticReference, RefractionAtEveryWavelengthMatches) {
  double worst = 0.0;
  int compared = 0;
  for (const json& state : reference()["states"]) {
    const Prescription p = preset(state);
    for (const json& w : state["refraction"]) {
      const double lambda = w["wavelength_nm"].get<double>();
      const double d = refraction_at(p, lambda) - w["refraction_D"].get<double>();
      EXPECT_NEAR(d, 0.0, 1e-6) << state["id"] << " at " << lambda << " nm";
      worst = std::max(worst, std::abs(d));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 9 * 32);  // 31 wavelengths and the reference (589.3 or 543 nm)
  RecordProperty("worst_refraction_difference_D", fmt::format("{:.3g}", worst));
}

// Chief-ray TCA, 450 vs 650 nm, at 0-40 deg for the 7 relaxed eyes and at 0.5 m for Navarro. The
// issue asks for < 1 %; both sides aim their chief rays to <= 1e-12 mm at the stop and solve the
// visual angle to <= 1e-10 mm on the retina (2e-8 arcmin), so 1e-6 arcmin (and 1e-6 um) is 50x
// that and far inside 1 %.
TEST(ChromaticReference, TransverseChromaticAberrationMatches) {
  int compared = 0;
  for (const json& state : reference()["states"]) {
    if (state["tca"].empty()) continue;
    const Prescription p = preset(state);
    for (const json& t : state["tca"]) {
      const double field = t["field_deg"].get<double>();
      const double distance = t["object_distance_m"].is_null() ? kInf : t["object_distance_m"].get<double>();
      ChromaticOptions o;
      o.centroid_grid = 0;
      const TransverseChromatic r = transverse_chromatic_aberration(p, field, distance, o);
      ASSERT_TRUE(r.ok) << state["id"] << " " << field << ": " << r.lost;
      const std::string where = state["id"].get<std::string>() + " field " + std::to_string(field);
      EXPECT_NEAR(r.tca_arcmin, t["tca_arcmin"].get<double>(), 1e-6) << where;
      EXPECT_NEAR(r.retina_um, t["retina_um"].get<double>(), 1e-6) << where;
      EXPECT_NEAR(r.short_angle_deg, t["short_angle_deg"].get<double>(), 1e-8) << where;
      EXPECT_NEAR(r.long_angle_deg, t["long_angle_deg"].get<double>(), 1e-8) << where;
      if (field != 0.0) EXPECT_LT(std::abs(r.tca_arcmin / t["tca_arcmin"].get<double>() - 1.0), 0.01) << where;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 7 * 5 + 2);
}

// --- closed-form cases ----------------------------------------------------------------------

// A reduced eye: one refracting sphere (R 5.55 mm) into a dispersive medium, the retina 22.22 mm
// behind it; the stop at the vertex or at the centre of curvature.
Prescription reduced_eye(bool stop_at_centre, double retina_radius_mm) {
  Prescription p;
  p.name = "reduced";
  Medium water{"water", 1.333, 589.3, {}};
  water.dispersion.law = DispersionLaw::Cornu;  // any dispersive law will do
  water.dispersion.cornu_n_inf = 1.3208;
  water.dispersion.cornu_k_nm = 6.9806;
  p.media = {{"air", 1.0, 589.3, {}}, water};
  auto surface = [](std::string name, double radius, double t, std::string medium, double n, SurfaceRole role) {
    Surface s;
    s.name = std::move(name);
    s.profile = radius == 0.0 ? SurfaceProfile{} : SurfaceProfile::from_radius(radius, 0.0);
    s.thickness_mm = t;
    s.medium = std::move(medium);
    s.index_after = n;
    s.role = role;
    s.semi_diameter_mm = role == SurfaceRole::Stop ? 1.0 : 0.0;
    return s;
  };
  if (stop_at_centre) {
    p.surfaces = {surface("cornea", 5.55, 5.55, "water", 1.333, SurfaceRole::Refract),
                  surface("stop", 0.0, 22.22 - 5.55, "water", 1.333, SurfaceRole::Stop)};
  } else {
    p.surfaces = {surface("stop", 0.0, 0.0, "air", 1.0, SurfaceRole::Stop),
                  surface("cornea", 5.55, 22.22, "water", 1.333, SurfaceRole::Refract)};
  }
  p.surfaces.push_back(surface("retina", retina_radius_mm, 0.0, "water", 1.333, SurfaceRole::Image));
  validate(p);
  return p;
}

// Refraction of one surface: the object vergence V with V + (n - 1)/R = n/d (R, d in metres).
TEST(ChromaticClosedForm, ReducedEyeRefraction) {
  const Prescription p = reduced_eye(false, 0.0);
  for (const RefractionAtWavelength& w : chromatic_refraction(p, {})) {
    const double n = p.media[1].index_at(w.wavelength_nm);
    EXPECT_NEAR(w.refraction_D, n / 22.22e-3 - (n - 1.0) / 5.55e-3, 1e-9) << w.wavelength_nm;
  }
}

// Stop at the vertex: the chief ray meets the surface at its vertex, sin(theta') = sin(theta)/n.
// The reference chief ray that reaches the same retina point has sin(phi)/n_ref = sin(theta)/n,
// so the TCA is asin(n_ref sin(theta)/n_450) - asin(n_ref sin(theta)/n_650), exactly, for any
// retina; negative (the 450 nm image seen nearer the axis). Tolerance 1e-7 arcmin: the solvers'
// 1e-10 mm on the retina is 2e-8 arcmin.
TEST(ChromaticClosedForm, StopAtTheVertexGivesSnellTca) {
  for (double retina : {0.0, -11.0}) {
    const Prescription p = reduced_eye(false, retina);
    const double n0 = 1.333, ns = p.media[1].index_at(450), nl = p.media[1].index_at(650);
    for (double field : {5.0, 20.0, -20.0, 40.0}) {
      const double s = std::sin(field * std::numbers::pi / 180.0);
      const double expected =
          std::abs(60.0 * 180.0 / std::numbers::pi * (std::asin(n0 * s / ns) - std::asin(n0 * s / nl)));
      const TransverseChromatic t = transverse_chromatic_aberration(p, field, kInf, {});
      ASSERT_TRUE(t.ok) << t.lost;
      EXPECT_NEAR(t.tca_arcmin, -expected, 1e-7) << field << " deg, retina " << retina;
      EXPECT_LT(t.retina_um, 0.0);  // signed like the TCA, whatever the field's sign
    }
  }
}

// Stop at the centre of curvature (the nodal point): the chief ray meets the surface along its
// normal, is not refracted, and reaches the same retina point at every wavelength: no TCA.
TEST(ChromaticClosedForm, StopAtTheNodalPointGivesNoTca) {
  const Prescription p = reduced_eye(true, -11.0);
  for (double field : {10.0, 30.0}) {
    const TransverseChromatic t = transverse_chromatic_aberration(p, field, kInf, {});
    ASSERT_TRUE(t.ok) << t.lost;
    EXPECT_NEAR(t.tca_arcmin, 0.0, 1e-7);
    EXPECT_NEAR(t.retina_um, 0.0, 1e-7);
    EXPECT_NEAR(t.short_angle_deg, field, 1e-8);
  }
}

// --- published numbers --------------------------------------------------------------------

// The issue: Navarro's eye is "about 2.1 D more myopic at 400 nm than at 589 nm and 0.4 D less at
// 700 nm". "About" read as the one decimal given: +-0.05 D.
TEST(ChromaticPublished, NavarroAsTheIssueStates) {
  const Prescription p = eye("navarro");
  EXPECT_NEAR(relative(p, 400), -2.1, 0.05);
  EXPECT_NEAR(relative(p, 700), 0.4, 0.05);
}

// shared/optics/eye-models.md section 5d (an independent computation with the raw formula
// indices, printed to 2 decimals): refraction -2.08 D at 400 nm, -0.68 at 486.1, -0.23 at 543,
// -0.16 at 555, +0.01 at 589.3, +0.27 at 656.3, +0.40 at 700. Relative to 589.3 nm the raw and
// the anchored indices give the same curve to 1e-3 D, so the tolerance is the two roundings
// (2 x 0.005) plus that: 0.011 D.
TEST(ChromaticPublished, NavarroMatchesEyeModelsSection5d) {
  const Prescription p = eye("navarro");
  const std::pair<double, double> em[] = {{400, -2.08}, {486.1, -0.68}, {543, -0.23},
                                          {555, -0.16}, {656.3, 0.27},  {700, 0.40}};
  for (auto [lambda, value] : em) EXPECT_NEAR(relative(p, lambda), value - 0.01, 0.011) << lambda;
}

// eye-models.md section 7 (computed there, 3 decimals): the Arizona eye with its Abbe line is
// -0.549 D at 486.1 nm, -0.187 at 555, +0.344 at 656.3 (-0.007 at 589.3). The line passes
// through n_d, so anchoring changes nothing: tolerance the rounding, 0.0005 D (+1e-5).
TEST(ChromaticPublished, ArizonaMatchesEyeModelsSection7) {
  const Prescription p = eye("arizona");
  EXPECT_NEAR(refraction_at(p, 486.1), -0.549, 0.00051);
  EXPECT_NEAR(refraction_at(p, 555), -0.187, 0.00051);
  EXPECT_NEAR(refraction_at(p, 656.3), 0.344, 0.00051);
}

// Measured LCA. Thibos et al. (1992) "The chromatic eye", Appl. Opt. 31:3594: refraction
// Rx = p - q/(lambda - c), q = 633.46 D nm, c = 214.102 nm (p only sets the zero; it cancels in
// differences). Atchison & Smith (2005) JOSA A 22:29, Eq. 5: R = 1.60911 - 6.70941e5/l^2 +
// 5.55334e10/l^4 - 5.59998e15/l^6 (l in nm). Both are fits to psychophysical LCA data; the
// schematic eyes' dispersion comes from Le Grand's index measurements instead. From 500 to 700 nm
// Navarro's eye follows both within 0.05 D (the two formulas differ from each other by up to
// 0.035 D there). Below 500 nm it is more myopic: at 400 nm by 0.38 D (Thibos) and 0.31 D (A&S)
// -- Le Grand's short-wavelength dispersion is steeper than the measured LCA. That excess is
// pinned to [0.25, 0.45] D so a change of it is noticed.
double thibos(double l) { return -633.46 / (l - 214.102); }
double atchison_smith(double l) {
  return 1.60911 - 6.70941e5 / (l * l) + 5.55334e10 / std::pow(l, 4) - 5.59998e15 / std::pow(l, 6);
}

TEST(ChromaticPublished, NavarroAgainstMeasuredLca) {
  const Prescription p = eye("navarro");
  for (double l = 500; l <= 700; l += 10) {
    EXPECT_NEAR(relative(p, l), thibos(l) - thibos(589.3), 0.05) << l;
    EXPECT_NEAR(relative(p, l), atchison_smith(l) - atchison_smith(589.3), 0.05) << l;
  }
  const double excess_thibos = (thibos(400) - thibos(589.3)) - relative(p, 400);
  const double excess_as = (atchison_smith(400) - atchison_smith(589.3)) - relative(p, 400);
  EXPECT_GT(excess_thibos, 0.25);
  EXPECT_LT(excess_thibos, 0.45);
  EXPECT_GT(excess_as, 0.25);
  EXPECT_LT(excess_as, 0.45);
}

// The chromatic section follows the camera's accommodation. Atchison, Smith & Waterworth (1993)
// Optom. Vis. Sci. 70:716 predict, from reduced eyes and ray tracing of schematic eyes, that the
// 400-700 nm LCA grows by 0.04-0.05 D (2.1-2.6 %) per dioptre of accommodation. The models
// accommodate differently (Navarro and Arizona raise the lens index, Gullstrand and Le Grand
// interpolate towards their accommodated eyes), so the band is widened by 0.015 D each side;
// observed 0.046 (legrand) to 0.056 (navarro) D per dioptre at 4 D.
TEST(ChromaticPublished, LcaGrowsWithAccommodation) {
  for (const char* model : {"navarro", "arizona", "gullstrand", "legrand"}) {
    const Prescription relaxed = eye(model), accommodated = eye(model, "", 4.0);
    auto lca = [](const Prescription& p) { return refraction_at(p, 700) - refraction_at(p, 400); };
    const double produced = refraction_D(relaxed) - refraction_D(accommodated);
    const double per_dioptre = (lca(accommodated) - lca(relaxed)) / produced;
    EXPECT_GT(per_dioptre, 0.04 - 0.015) << model;
    EXPECT_LT(per_dioptre, 0.05 + 0.015) << model;
  }
}

// Measured TCA. Winter et al. (2016) J. Vis. 16(14):9, 4 subjects, 543 vs 842 nm: TCA grows
// linearly with the field, 0.21 arcmin/deg on average (0.41 arcmin/deg for 430-770 nm, their
// conversion). With the chromatic eye's dispersion n = a + b/(lambda - c), b = 0.004685 um,
// c = 0.214102 um (Thibos 1992 p. 3596), 450-650 nm is 1.34 times 543-842 nm: 0.28 arcmin/deg.
// The subjects differ and the models' dispersions differ from the chromatic eye's (LCA above),
// so only the magnitude is checked: every model within a factor 1.5 of 0.28 arcmin/deg at
// 20 deg. Catches a wrong unit (x60), a wrong wavelength pair or the wrong ray.
TEST(ChromaticPublished, TcaMagnitudeAsMeasured) {
  auto dn = [](double l_nm) { return 0.004685 / (l_nm * 1e-3 - 0.214102); };
  const double slope = 0.21 * (dn(450) - dn(650)) / (dn(543) - dn(842));
  EXPECT_NEAR(slope, 0.28, 0.005);
  for (const char* model : {"gullstrand", "legrand", "kooijman", "navarro", "escudero-sanz", "arizona"}) {
    const TransverseChromatic t = transverse_chromatic_aberration(eye(model), 20.0, kInf, {});
    ASSERT_TRUE(t.ok) << model;
    const double model_slope = std::abs(t.tca_arcmin) / 20.0;
    EXPECT_GT(model_slope, slope / 1.5) << model;
    EXPECT_LT(model_slope, slope * 1.5) << model;
  }
}

// --- Gullstrand and Kooijman: assumed dispersion, reference wavelength unchanged ---------------

TEST(ChromaticDispersion, AssumedLawsLeaveTheReferenceEyeAlone) {
  for (const char* model : {"gullstrand", "kooijman"}) {
    const Prescription p = eye(model);
    EXPECT_TRUE(p.dispersion_assumed) << model;
    EXPECT_FALSE(p.dispersion_source.empty()) << model;
    for (const Medium& m : p.media) {
      EXPECT_NE(m.dispersion.law, DispersionLaw::None) << model << " " << m.name;
      EXPECT_EQ(m.index_at(589.3), m.index) << model << " " << m.name;  // bit for bit
      EXPECT_GT(m.index_at(450), m.index_at(650)) << model << " " << m.name;
    }
    const Prescription same = at_wavelength(p, 589.3);
    for (size_t i = 0; i < p.surfaces.size(); ++i) EXPECT_EQ(same.surfaces[i].index_after, p.surfaces[i].index_after);
    EXPECT_EQ(refraction_D(same), refraction_D(p));
  }
  // Gullstrand's cortex and nucleus change alike (the lens law): their step stays 0.02.
  const Prescription g = eye("gullstrand");
  const Medium *cortex = g.find_medium("lens cortex"), *nucleus = g.find_medium("lens nucleus");
  EXPECT_NEAR(nucleus->index_at(400) - cortex->index_at(400), 0.02, 1e-12);
  for (const char* model : {"navarro", "legrand", "arizona", "escudero-sanz"}) {
    EXPECT_FALSE(eye(model).dispersion_assumed) << model;
    EXPECT_FALSE(eye(model).dispersion_source.empty()) << model;
  }
}

// The accommodated Arizona lens keeps V_d = 51.9 for its larger n_d: n_F - n_C = (n_d - 1)/V_d.
TEST(ChromaticDispersion, ArizonaAccommodatedLensKeepsItsAbbeNumber) {
  const Prescription arizona = eye("arizona", "", 4.0);  // the medium lives in it
  const Medium* lens = arizona.find_medium("lens");
  EXPECT_NEAR(lens->index_at(486.1) - lens->index_at(656.3), (lens->index - 1.0) / 51.9, 1e-12);
}

// --- options, report, plot --------------------------------------------------------------------

TEST(ChromaticOptionsCheck, BadWavelengthsNameTheOption) {
  auto message = [](ChromaticOptions o) {
    try {
      validate(o);
    } catch (const OpticsError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ChromaticOptions o;
  o.min_wavelength_nm = 300;
  EXPECT_NE(message(o).find("chromatic range: 300 nm is outside [360, 1020] nm"), std::string::npos) << message(o);
  o = {};
  o.max_wavelength_nm = 1100;
  EXPECT_NE(message(o).find("chromatic range: 1100 nm"), std::string::npos) << message(o);
  o = {};
  o.min_wavelength_nm = 700, o.max_wavelength_nm = 400;
  EXPECT_NE(message(o).find("chromatic range"), std::string::npos) << message(o);
  o = {};
  o.step_nm = 0;
  EXPECT_NE(message(o).find("chromatic step"), std::string::npos) << message(o);
  o = {};
  o.tca_long_nm = 1050;
  EXPECT_NE(message(o).find("tca wavelengths: 1050 nm"), std::string::npos) << message(o);
  o = {};
  o.tca_short_nm = 650, o.tca_long_nm = 450;
  EXPECT_NE(message(o).find("tca wavelengths"), std::string::npos) << message(o);
  o = {};
  o.min_wavelength_nm = std::nan("");
  EXPECT_NE(message(o).find("chromatic range"), std::string::npos) << message(o);
  EXPECT_THROW(chromatic_refraction(eye("navarro"), o), OpticsError);
  ReportOptions r;
  r.chromatic.min_wavelength_nm = 300;
  EXPECT_THROW(optics_report(eye("navarro"), r), OpticsError);
}

TEST(ChromaticRefraction, WavelengthsFromMinToMaxEveryStep) {
  ChromaticOptions o;
  o.min_wavelength_nm = 400, o.max_wavelength_nm = 705, o.step_nm = 50;
  const auto list = chromatic_refraction(eye("legrand"), o);
  ASSERT_EQ(list.size(), 8u);  // 400, 450, ..., 700, 705
  EXPECT_EQ(list[6].wavelength_nm, 700.0);
  EXPECT_EQ(list[7].wavelength_nm, 705.0);
  for (size_t i = 1; i < list.size(); ++i)
    EXPECT_GT(list[i].refraction_D, list[i - 1].refraction_D);  // normal dispersion
}

TEST(ChromaticReport, JsonKeysAndValues) {
  const json r = optics_report(eye("navarro"));
  ASSERT_TRUE(r.contains("chromatic_refraction"));
  const json& list = r["chromatic_refraction"];
  ASSERT_EQ(list.size(), 31u);
  EXPECT_EQ(list[0]["wavelength_nm"].get<double>(), 400.0);
  EXPECT_EQ(list[30]["wavelength_nm"].get<double>(), 700.0);
  EXPECT_NEAR(list[0]["refraction_diopters"].get<double>(), -2.0964, 1e-4);
  EXPECT_NEAR(r["chromatic"]["lca_diopters"].get<double>(),
              list[30]["refraction_diopters"].get<double>() - list[0]["refraction_diopters"].get<double>(), 2e-6);
  EXPECT_EQ(r["chromatic"]["step_nm"].get<double>(), 10.0);
  EXPECT_EQ(r["dispersion"]["assumed"].get<bool>(), false);
  EXPECT_EQ(r["dispersion"]["media"][0]["law"].get<std::string>(), "navarro-herzberger");
  const json& tca = r["tca"];
  EXPECT_EQ(tca["short_wavelength_nm"].get<double>(), 450.0);
  EXPECT_EQ(tca["long_wavelength_nm"].get<double>(), 650.0);
  ASSERT_EQ(tca["fields"].size(), 5u);
  EXPECT_EQ(tca["fields"][2]["field_deg"].get<double>(), 20.0);
  EXPECT_NEAR(tca["fields"][2]["tca_arcmin"].get<double>(), -6.600, 0.001);
  EXPECT_FALSE(tca["fields"][2]["centroid_tca_arcmin"].is_null());
  EXPECT_EQ(tca["fields"][0]["tca_arcmin"].get<double>(), 0.0);

  const json g = optics_report(eye("gullstrand"));
  EXPECT_TRUE(g["dispersion"]["assumed"].get<bool>());
  const std::string text = format_report(g);
  EXPECT_NE(text.find("dispersion (assumed"), std::string::npos) << text;
  EXPECT_NE(text.find("LCA 2.532 D"), std::string::npos) << text;
  EXPECT_NE(text.find("  400  -2.136"), std::string::npos) << text;
  EXPECT_NE(text.find("field  20.0 deg: TCA   -6.527 arcmin"), std::string::npos) << text;
}

// A lost chief ray is reported per field, not thrown: the 4.82 mm cornea of Le Grand's eye
// vignettes every ray at 80 deg.
TEST(ChromaticReport, LostChiefRayIsNullWithAReason) {
  ReportOptions o;
  o.fields_deg = {80.0};
  const json f = optics_report(eye("legrand"), o)["tca"]["fields"][0];
  EXPECT_TRUE(f["tca_arcmin"].is_null());
  EXPECT_FALSE(f["lost"].get<std::string>().empty());
}

TEST(ChromaticPlot, CurveAxesAndErrors) {
  const json r = optics_report(eye("navarro"));
  const RgbImage img = chromatic_plot(r, 720, 400);
  ASSERT_EQ(img.rgb.size(), 720u * 400u * 3u);
  int curve = 0, dark = 0;
  for (size_t i = 0; i < img.rgb.size(); i += 3) {
    curve += img.rgb[i] == 31 && img.rgb[i + 1] == 119 && img.rgb[i + 2] == 180;
    dark += img.rgb[i] == 0 && img.rgb[i + 1] == 0 && img.rgb[i + 2] == 0;
  }
  EXPECT_GT(curve, 600);  // a 4-pixel-wide line across ~650 pixels, and the points
  EXPECT_GT(dark, 1500);  // axes box and labels
  EXPECT_THROW(chromatic_plot(r, 100, 400), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
