// The polychromatic PSF, Strehl ratio, encircled energy and MTF (optics/polychromatic_psf.h) and
// the luminous efficiency V(lambda) it is weighted by (optics/luminous_efficiency.h), against
// published values and analytic answers: CIE V(lambda) at its tabulated wavelengths and its
// integral; for a system without dispersion and without aberration, the V-weighted sum of the
// diffraction-limited MTFs (2/pi)(acos nu - nu sqrt(1 - nu^2)), nu = f lambda / D, and of
// Rayleigh's encircled energy 1 - J0^2 - J1^2; energy conservation; the sign of the lateral
// colour against the real-ray spot's centroid; Navarro's eye's polychromatic Strehl ratio below
// its monochromatic one at 555 nm (the chromatic difference of focus blurs the other wavelengths).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/single_surface.h"
#include "../support/unity_id.h"
#include "optics/chromatic.h"
#include "optics/encircled_energy.h"
#include "optics/eye_models.h"
#include "optics/luminous_efficiency.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/polychromatic_psf.h"
#include "optics/psf.h"
#include "optics/spot.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

Prescription navarro() {
  EyeOptions o;
  o.model = "navarro";
  return make_eye(o);
}

// CIE 1924 V(lambda) (= 1931 y-bar) at tabulated wavelengths, as published (CIE 15, Table T.4;
// e.g. 0.503 at 510 and 610 nm, the two half-maximum points of the 5 nm table).
TEST(LuminousEfficiency, MatchesPublishedValues) {
  const std::vector<std::pair<double, double>> published = {{380, 0.000039}, {450, 0.038},   {500, 0.323}, {510, 0.503},
                                                            {555, 1.0},      {600, 0.631},   {610, 0.503}, {650, 0.107},
                                                            {700, 0.004102}, {780, 0.000015}};
  for (const auto& [nm, v] : published) EXPECT_NEAR(photopic_luminous_efficiency(nm), v, 1e-9) << nm;
  EXPECT_NEAR(photopic_luminous_efficiency(557.5), 0.5 * (1.0 + 0.995), 1e-12);  // linear between rows
  EXPECT_EQ(photopic_luminous_efficiency(379.0), 0.0);
  EXPECT_EQ(photopic_luminous_efficiency(std::nan("")), 0.0);
}

// The integral of y-bar over wavelength is 106.857 nm (the CIE 1 nm table's sum, which fixes
// the luminance of the equal-energy spectrum: 683 lm/W x 106.857); the 5 nm table's rectangle
// sum agrees to its rounding.
TEST(LuminousEfficiency, IntegratesToTheCieTotal) {
  double sum = 0.0;
  for (double nm = 380.0; nm <= 780.0; nm += 5.0) sum += 5.0 * photopic_luminous_efficiency(nm);
  EXPECT_NEAR(sum, 106.857, 0.02);
}

// Dispersion-free stigmatic surface (single_surface.h: its media have no dispersion law), 1 mm
// stop radius, on axis: every wavelength's PSF is the Airy pattern of its own lambda / D, centred
// on the same point, on the same retinal scale.
struct Achromatic : ::testing::Test {
  Prescription p = test::stigmatic_surface(1.0);
  PolychromaticPsf psf = polychromatic_psf(p, WavefrontOptions{}, PolychromaticOptions{});

  // The weights the summed MTF and encircled energy must carry: V x trapezoid width, summed to 1.
  std::vector<std::pair<double, double>> weights() const {
    std::vector<std::pair<double, double>> w;
    double total = 0.0;
    for (double nm = 400.0; nm <= 700.0 + 1e-9; nm += 10.0) {
      const double v = photopic_luminous_efficiency(nm) * ((nm == 400.0 || nm > 699.0) ? 5.0 : 10.0);
      w.push_back({nm, v});
      total += v;
    }
    for (auto& [nm, v] : w) v /= total;
    return w;
  }
};

TEST_F(Achromatic, MtfIsTheWeightedDiffractionLimitedMtf) {
  ASSERT_EQ(psf.components.size(), 31u);
  const double d_mm = 2.0;
  const double mm_per_rad = psf.reference_scale.tangential_mm_per_rad;
  std::vector<double> freqs;
  for (double f = 0.0; f < 60.0; f += 4.0) freqs.push_back(f);  // cut-off at 400 nm: 87 cycles/deg
  const std::vector<MtfPoint> mtf = polychromatic_mtf(psf, freqs);
  for (const MtfPoint& m : mtf) {
    double expected = 0.0;
    for (const auto& [nm, w] : weights())
      expected += w * diffraction_limited_mtf(m.freq_cpd / kRadPerDeg * nm * 1e-6 / d_mm);
    EXPECT_NEAR(m.tangential, expected, 0.01) << m.freq_cpd;
    EXPECT_NEAR(m.sagittal, expected, 0.01) << m.freq_cpd;
    EXPECT_NEAR(polychromatic_diffraction_limit(psf, m.freq_cpd).tangential, expected, 1e-3) << m.freq_cpd;
    EXPECT_NEAR(m.tangential_cyc_per_mm, m.freq_cpd / kRadPerDeg / mm_per_rad, 1e-9);
  }
}

TEST_F(Achromatic, StrehlIsOneAndEnergyIsConserved) {
  EXPECT_NEAR(psf.strehl, 1.0, 1e-3);
  EXPECT_NEAR(glm::length(psf.peak_um), 0.0, 0.05);
  EXPECT_NEAR(psf.energy, 1.0, 0.02);  // the bilinear resampling of a PSF sampled at lambda / 4D
  for (const PolychromaticComponent& c : psf.components) EXPECT_NEAR(glm::length(c.offset_um), 0.0, 1e-9);
}

// Rayleigh's encircled energy of each wavelength's Airy pattern (which also checks that the
// wavelengths' energies are normalised and weighted as stated), 1 - J0^2(v) - J1^2(v) with
// v = pi D theta / lambda, weighted and summed; its 50 % and 80 % radii by bisection.
TEST_F(Achromatic, EncircledEnergyIsTheWeightedRayleighSum) {
  const double mm_per_rad = psf.reference_scale.tangential_mm_per_rad;
  auto fraction = [&](double r_um) {
    double sum = 0.0;
    for (const auto& [nm, w] : weights()) {
      const double v = std::numbers::pi * 2.0 * (r_um * 1e-3 / mm_per_rad) / (nm * 1e-6);
      sum += w * (1.0 - std::pow(std::cyl_bessel_j(0.0, v), 2) - std::pow(std::cyl_bessel_j(1.0, v), 2));
    }
    return sum;
  };
  auto radius = [&](double target) {
    double lo = 0.0, hi = 100.0;
    for (int i = 0; i < 60; ++i) (fraction(0.5 * (lo + hi)) < target ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  EXPECT_NEAR(psf.ee50_um / radius(0.5), 1.0, 0.003);
  EXPECT_NEAR(psf.ee80_um / radius(0.8), 1.0, 0.003);
}

TEST(PolychromaticPsf, WeightsFollowVAndTheSource) {
  const Prescription p = test::stigmatic_surface(1.0);
  PolychromaticOptions o;
  o.min_wavelength_nm = 500.0, o.max_wavelength_nm = 600.0, o.step_nm = 50.0;
  o.source = [](double nm) { return nm < 550.0 ? 2.0 : 1.0; };
  o.source_name = "test";
  const PolychromaticPsf psf = polychromatic_psf(p, WavefrontOptions{}, o);
  ASSERT_EQ(psf.components.size(), 3u);
  const double w[3] = {2.0 * 0.323 * 25.0, 0.994950 * 50.0, 0.631 * 25.0};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(psf.components[i].weight, w[i] / (w[0] + w[1] + w[2]), 1e-9);
  EXPECT_EQ(psf.source_name, "test");
}

// The chromatic difference of focus blurs every wavelength but the one the retina is focused
// for: Navarro's retina is at the paraxial focus of 589.3 nm, where its 3 mm Strehl ratio is
// 0.755 (docs/wavefront.md; Marechal's 0.753), so the V-weighted Strehl ratio lies well below
// that and below the best of its wavelengths' (a weighted mean of values each at most its own
// peak). It is above the 555 nm one (0.19): at 555 nm this retina is 0.17 D out of focus, and the
// wavelengths from 570 to 620 nm, nearer focus, carry 40 % of V's weight.
TEST(PolychromaticPsf, NavarroStrehlIsBelowItsInFocusStrehl) {
  const Prescription p = navarro();
  WavefrontOptions o;
  o.pupil_radius_mm = 1.5;
  const PolychromaticPsf poly = polychromatic_psf(p, o, PolychromaticOptions{});
  o.wavelength_nm = 589.3;
  const double in_focus = trace_psf(p, o).psf.strehl;
  o.wavelength_nm = 555.0;
  const double at_555 = trace_psf(p, o).psf.strehl;
  double best = 0.0;
  for (const PolychromaticComponent& c : poly.components) best = std::max(best, c.strehl);
  EXPECT_LT(poly.strehl, 0.8 * in_focus);
  EXPECT_LT(poly.strehl, best);
  EXPECT_GT(poly.strehl, at_555);
  EXPECT_NEAR(poly.energy, 1.0, 0.02);
  const std::vector<MtfPoint> mtf = polychromatic_mtf(poly, {0.0, 10.0, 30.0});
  EXPECT_NEAR(mtf[0].tangential, 1.0, 1e-12);
  for (const MtfPoint& m : mtf) {
    EXPECT_LE(m.tangential, polychromatic_diffraction_limit(poly, m.freq_cpd).tangential + 1e-9);
    EXPECT_NEAR(m.tangential, m.sagittal, 1e-9);  // on axis
  }
}

// The sign that places each wavelength's PSF on the retina (displacement_um): the PSF's centroid
// (its own coordinates, tangential axis) and the real-ray spot's centroid both sit off the chief
// ray at 20 degrees (coma), on the same side by the same amount: a geometric-optics centroid
// equals the diffraction PSF's (the mean wavefront slope).
TEST(PolychromaticPsf, PsfAxesFollowTheRetinaLikeTheSpot) {
  const Prescription p = navarro();
  WavefrontOptions o;
  o.field_deg = 20.0;  // the pupil: the real iris (as the spot's), inside the paraxial disc
  const TracedPsf t = trace_psf(p, o);
  const double psf_centroid_um = t.psf.centroid_rad.y * t.psf.scale.tangential_mm_per_rad * 1000.0;
  const SpotResult spot = trace_spot(p, {20.0, o.object_distance_m, 256});
  const ChiefRay chief = trace_chief_ray(p, 20.0);
  const double spot_centroid_um = 1000.0 * (image_coordinate_mm(p, spot.centroid_mm) - chief.image_coordinate_mm);
  ASSERT_GT(std::abs(spot_centroid_um), 1.0);
  EXPECT_NEAR(psf_centroid_um, spot_centroid_um, 0.1 * std::abs(spot_centroid_um));
}

TEST(PolychromaticPsf, BadOptionsAreErrors) {
  PolychromaticOptions o;
  o.min_wavelength_nm = 370.0;
  EXPECT_THROW(validate(o), OpticsError);
  o = {};
  o.max_wavelength_nm = 800.0;
  EXPECT_THROW(validate(o), OpticsError);
  o = {};
  o.step_nm = 0.0;
  EXPECT_THROW(validate(o), OpticsError);
  o = {};
  o.min_wavelength_nm = 600.0, o.max_wavelength_nm = 500.0;
  EXPECT_THROW(validate(o), OpticsError);
  o = {};
  o.source = [](double) { return -1.0; };
  EXPECT_THROW(polychromatic_psf(test::stigmatic_surface(1.0), WavefrontOptions{}, o), OpticsError);
  const std::vector<double> w = polychromatic_wavelengths({400.0, 705.0, 10.0, {}, ""});
  EXPECT_EQ(w.size(), 32u);
  EXPECT_EQ(w.back(), 705.0);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// Lateral colour: the summed PSF's centroid is the weighted mean of the wavelengths' centroids,
// and a PSF's centroid is its real-ray spot's (the mean wavefront slope). So the V-weighted mean
// of the spots' centroids at each wavelength (trace_spot through the model at that wavelength,
// an independent geometric trace), measured from the reference wavelength's chief ray, is where
// the polychromatic PSF's centroid must be: Navarro at 20 degrees, whose 450-650 nm TCA is
// 31 um on the retina (a 2.65 mm iris: a 3 mm entrance pupil, the pupil of both).
TEST(PolychromaticPsf, CentroidIsTheWeightedSpotCentroid) {
  EyeOptions eye;
  eye.model = "navarro";
  eye.pupil_diameter_mm = 2.6484;
  const Prescription p = make_eye(eye);
  WavefrontOptions o;
  o.field_deg = 20.0;
  PolychromaticOptions poly;
  poly.step_nm = 20.0;
  const PolychromaticPsf psf = polychromatic_psf(p, o, poly);
  const double reference = trace_chief_ray(p, 20.0).image_coordinate_mm;
  double expected = 0.0, total = 0.0;
  for (const PolychromaticComponent& c : psf.components) {
    const Prescription at = at_wavelength(p, c.wavelength_nm);
    const SpotResult spot = trace_spot(at, {20.0, o.object_distance_m, 128});
    expected += c.weight * 1000.0 * (image_coordinate_mm(p, spot.centroid_mm) - reference);
    total += c.weight;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  ASSERT_GT(std::abs(expected), 5.0);
  // -13.88 against -14.38 um when written (the spots fill the real pupil, 128 across).
  EXPECT_NEAR(psf.centroid_um.y, expected, 0.05 * std::abs(expected));
  EXPECT_NEAR(psf.centroid_um.x, 0.0, 1e-6);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
