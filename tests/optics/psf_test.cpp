// PSF, Strehl ratio, encircled energy (optics/psf.h) and MTF (optics/mtf.h) against analytic
// answers: the Airy pattern of an aberration-free circular pupil (first zero at 1.2197 lambda / D,
// 3.8317 / pi; Airy 1835), Rayleigh's encircled energy of it, 1 - J0(v)^2 - J1(v)^2 with
// v = pi D r / (lambda f) (Rayleigh 1881; 83.8 % inside the first dark ring), the
// diffraction-limited MTF (2/pi)(acos nu - nu sqrt(1 - nu^2)), the Strehl ratio of pure defocus
// (sin(pi a) / (pi a))^2 for W = a rho^2 waves, and Marechal's exp(-(2 pi sigma)^2) for small
// RMS sigma; the MTF against a direct autocorrelation of the pupil samples.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "../support/single_surface.h"
#include "../support/unity_id.h"
#include "optics/encircled_energy.h"
#include "optics/eye_models.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"
#include "optics/psf.h"
#include "optics/wavefront.h"
#include "optics/zernike.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kPi = std::numbers::pi;
constexpr double kAiryZero = 3.831705970207512 / kPi;  // first zero of J1 / pi: 1.2197 lambda / D

// A wavefront on the grid x grid cell centres of the unit disc (as trace_wavefront samples it),
// OPD in waves given by a function of the normalised pupil point; on axis, 555 nm.
WavefrontResult synthetic(int grid, double radius_mm, const std::function<double(glm::dvec2)>& opd_waves) {
  WavefrontResult w;
  w.grid = grid;
  w.wavelength_nm = 555.0;
  w.pupil_radius_mm = radius_mm;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const glm::dvec2 u(-1.0 + (i + 0.5) * 2.0 / grid, -1.0 + (j + 0.5) * 2.0 / grid);
      if (glm::dot(u, u) > 1.0) continue;
      w.pupil_points.push_back(u);
      w.opd_waves.push_back(opd_waves(u));
    }
  w.rays_in_pupil = static_cast<int>(w.pupil_points.size());
  return w;
}

// 16.7 mm per radian: a 60 D eye's front focal length, the same tangentially and sagittally.
const RetinalScale kEyeScale{1000.0 / 60.0, 1000.0 / 60.0};

double lambda_over_d(const Psf& p) { return p.wavelength_nm * 1e-6 / (2.0 * p.pupil_radius_mm); }

// Angle (rad) of the first minimum along +x: the smallest FFT sample of the row through the
// centre, then a golden-section search between its neighbours on the directly summed PSF.
double first_minimum_rad(const WavefrontResult& w, const Psf& p) {
  const int n = p.fft_size, c = n / 2;
  int i = c + 1;
  while (i + 1 < n && p.at(i + 1, c) < p.at(i, c)) ++i;
  double a = (i - 1 - c) * p.sample_x_rad, b = (i + 1 - c) * p.sample_x_rad;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int k = 0; k < 60; ++k) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    (psf_at(w, 1.0, {x1, 0.0}) < psf_at(w, 1.0, {x2, 0.0}) ? b : a) =
        (psf_at(w, 1.0, {x1, 0.0}) < psf_at(w, 1.0, {x2, 0.0}) ? x2 : x1);
  }
  return 0.5 * (a + b);
}

// v (pi D r / lambda f) where Rayleigh's encircled energy 1 - J0^2 - J1^2 reaches this fraction,
// by bisection on its monotonic rise up to the first zero of J1 (83.8 %).
double rayleigh_ee_v(double fraction) {
  double lo = 0.0, hi = 3.8317;
  for (int i = 0; i < 100; ++i) {
    const double v = 0.5 * (lo + hi);
    const double ee = 1.0 - std::pow(std::cyl_bessel_j(0.0, v), 2) - std::pow(std::cyl_bessel_j(1.0, v), 2);
    (ee < fraction ? lo : hi) = v;
  }
  return 0.5 * (lo + hi);
}

// The stigmatic single surface of tests/support/single_surface.h, at 555 nm.
Prescription stigmatic_surface(double stop_radius_mm) { return test::stigmatic_surface(stop_radius_mm, 555.0); }

// The traced stigmatic surface, its real stop defining the pupil: an Airy pattern on the image
// plane with its first zero at 1.22 lambda N, N = 1 / (2 n' sin u') the working f-number from the
// marginal ray (edge of the 1 mm stop, on the ellipsoid, to the focus: geometry, not the trace).
TEST(PsfAiry, StigmaticSurfaceHasItsFirstZeroAt122LambdaN) {
  const double n = 1.5, r = 1.0;
  const Prescription p = stigmatic_surface(r);
  WavefrontOptions o;
  o.grid = 128;
  o.clip_at_stop = true;
  const WavefrontResult w = trace_wavefront(p, o);
  const RetinalScale scale = retinal_scale(p, 0.0, o.object_distance_m, 0.0);
  EXPECT_NEAR(scale.tangential_mm_per_rad, 10.0 / (n - 1.0), 1e-4);  // front focal length R / (n - 1)
  const Psf psf = compute_psf(w, scale);
  const glm::dvec3 edge(r, 0.0, p.surfaces[1].profile.sag(r * r)), focus(0.0, 0.0, 30.0);
  const double sin_u = r / glm::distance(edge, focus);
  const double working_n = 1.0 / (2.0 * n * sin_u);
  const double zero_um = first_minimum_rad(w, psf) * scale.sagittal_mm_per_rad * 1000.0;
  EXPECT_NEAR(zero_um / (1.21967 * 0.555 * working_n), 1.0, 0.01) << zero_um;
  EXPECT_NEAR(psf.strehl, 1.0, 1e-6);
  // The exit-pupil form of the scale: lambda R / (n' N delta'), the exit pupil at the stop (the
  // vertex), delta' = delta, R the reference sphere's radius.
  const double exit_sample_um = 555e-6 * w.reference_radius_mm / (n * psf.fft_size * psf.pupil_spacing_mm) * 1000.0;
  EXPECT_NEAR(psf.sample_x_um / exit_sample_um, 1.0, 1e-4);
}

TEST(PsfAiry, ZeroOpdGivesTheAiryPattern) {
  const WavefrontResult w = synthetic(128, 1.5, [](glm::dvec2) { return 0.0; });
  const Psf p = compute_psf(w, kEyeScale);
  EXPECT_EQ(p.fft_size, 512);  // automatic: the power of two >= 4 x 128
  EXPECT_TRUE(p.warning.empty());
  const double zero = first_minimum_rad(w, p) / lambda_over_d(p);
  EXPECT_NEAR(zero / kAiryZero, 1.0, 0.01) << zero;
  // The samples along x follow (2 J1(v) / v)^2, v = pi D angle / lambda (the grid's staircase
  // disc is the difference).
  for (int k = 1; k < 40; ++k) {
    const double v = kPi * k * p.sample_x_rad / lambda_over_d(p);
    EXPECT_NEAR(p.at(p.fft_size / 2 + k, p.fft_size / 2), std::pow(2.0 * std::cyl_bessel_j(1.0, v) / v, 2), 2e-3) << k;
  }
  EXPECT_NEAR(p.strehl, 1.0, 1e-6);
  EXPECT_NEAR(p.strehl_phasor, 1.0, 1e-12);
  EXPECT_NEAR(p.at(p.fft_size / 2, p.fft_size / 2), 1.0, 1e-9);
}

TEST(PsfAiry, EncircledEnergyIsRayleighs) {
  const Psf p = compute_psf(synthetic(128, 1.5, [](glm::dvec2) { return 0.0; }), kEyeScale);
  // v = pi D r / (lambda f): the radius in um is v / pi x lambda / D x f.
  const double um_per_v = lambda_over_d(p) / kPi * kEyeScale.sagittal_mm_per_rad * 1000.0;
  std::printf("Rayleigh: EE50 at %.4f, EE80 at %.4f lambda N\n", rayleigh_ee_v(0.5) / kPi, rayleigh_ee_v(0.8) / kPi);
  // Exact for the sampled pupil (encircled_energy.h); the grid's staircase disc is 0.1 % off at 128.
  EXPECT_NEAR(p.ee50_um / (rayleigh_ee_v(0.5) * um_per_v), 1.0, 2e-3) << p.ee50_um;
  EXPECT_NEAR(p.ee80_um / (rayleigh_ee_v(0.8) * um_per_v), 1.0, 2e-3) << p.ee80_um;
  // 83.8 % inside the first dark ring (as a fraction: the radius is ill-conditioned there, where
  // the curve is flat, d EE / dv = 2 J1(v)^2 / v = 0).
  const double ee_first_zero = 1.0 - std::pow(std::cyl_bessel_j(0.0, 3.831705970207512), 2);
  EXPECT_NEAR(ee_first_zero, 0.838, 5e-4);
  EXPECT_NEAR(encircled_energy(p, 3.831705970207512 * um_per_v), ee_first_zero, 1e-3);
  // The same at every FFT size: the radii do not depend on the PSF's sampling.
  PsfOptions fine;
  fine.fft_size = 1024;
  const Psf q = compute_psf(synthetic(128, 1.5, [](glm::dvec2) { return 0.0; }), kEyeScale, fine);
  EXPECT_NEAR(q.ee50_um, p.ee50_um, 1e-6 * p.ee50_um);
  EXPECT_NEAR(q.ee80_um, p.ee80_um, 1e-6 * p.ee80_um);
}

TEST(PsfEnergy, ParsevalHoldsForAnAberratedPupil) {
  const WavefrontResult w =
      synthetic(64, 2.0, [](glm::dvec2 u) { return 0.3 * zernike(7, u.x, u.y) + 0.2 * zernike(12, u.x, u.y); });
  const Psf p = compute_psf(w, kEyeScale);
  double sum = 0.0;
  for (double v : p.intensity) sum += v;
  // Intensity is in units of the diffraction-limited peak M^2: the sum is N^2 M / M^2.
  const double n2 = static_cast<double>(p.fft_size) * p.fft_size;
  EXPECT_NEAR(sum / (n2 / p.pupil_samples), 1.0, 1e-9);
}

// The spectrum the encircled energy reads is the pupil's autocorrelation (two FFTs of 2 grid);
// it must equal the DFT of the N x N PSF's samples (the definition), term by term.
TEST(PsfEnergy, SpectrumFromThePupilIsThePsfsSpectrum) {
  const WavefrontResult w = synthetic(
      48, 2.0, [](glm::dvec2 u) { return 0.3 * zernike(7, u.x, u.y) + 0.4 * zernike(4, u.x, u.y) + 0.1 * u.y; });
  const Psf p = compute_psf(w, kEyeScale);
  ASSERT_FALSE(p.spectrum.terms.empty());
  Psf samples_only = p;
  samples_only.spectrum = {};
  const PsfSpectrum direct = psf_spectrum(samples_only);
  ASSERT_EQ(direct.reach, 48);  // N = 256: min(grid, N/2 - 1); the pupil's M = 128 reaches 48 too
  const int side = 2 * direct.reach + 1, inner = 2 * p.spectrum.reach + 1;
  double largest = 0.0, worst = 0.0;
  for (int ky = -direct.reach; ky <= direct.reach; ++ky)
    for (int kx = -direct.reach; kx <= direct.reach; ++kx) {
      const std::complex<double> d = direct.terms[static_cast<size_t>(ky + direct.reach) * side + kx + direct.reach];
      const bool in = std::abs(kx) <= p.spectrum.reach && std::abs(ky) <= p.spectrum.reach;
      const std::complex<double> q =
          in ? p.spectrum.terms[static_cast<size_t>(ky + p.spectrum.reach) * inner + kx + p.spectrum.reach] : 0.0;
      largest = std::max(largest, std::abs(d)), worst = std::max(worst, std::abs(d - q));
    }
  EXPECT_LT(worst, 1e-9 * largest);
  EXPECT_NEAR(p.spectrum.window_x_um, direct.window_x_um, 1e-9);
  EXPECT_NEAR(encircled_energy_radius(p, 0.5), encircled_energy_radius(samples_only, 0.5), 1e-6);
}

// The evaluator the peak search uses (separable tilt on the grid) is psf_at's direct sum.
TEST(PsfStrehl, EvaluatorIsTheDirectSum) {
  WavefrontResult w = synthetic(40, 1.5, [](glm::dvec2 u) { return 0.3 * zernike(7, u.x, u.y) + 0.2 * u.x; });
  w.pupil_points.push_back({0.013, -0.2});  // off the grid: summed the direct way
  w.opd_waves.push_back(0.1);
  const PsfEvaluator evaluate(w, 0.8);
  for (const glm::dvec2 a : {glm::dvec2(0.0), glm::dvec2(1e-4, -2e-4), glm::dvec2(-3e-4, 5e-5)})
    EXPECT_NEAR(evaluate.at(a), psf_at(w, 0.8, a), 1e-12) << a.x << " " << a.y;
}

TEST(PsfStrehl, DefocusMatchesItsClosedFormAndMarechal) {
  const double sigma = 0.05;  // waves RMS: c20 = sigma, W = sigma sqrt(3) (2 rho^2 - 1)
  const WavefrontResult w = synthetic(128, 1.5, [&](glm::dvec2 u) { return sigma * zernike(4, u.x, u.y); });
  const Psf p = compute_psf(w, kEyeScale);
  const double a = 2.0 * std::sqrt(3.0) * sigma;  // the rho^2 coefficient, waves
  const double exact = std::pow(std::sin(kPi * a) / (kPi * a), 2);
  const double marechal = std::exp(-std::pow(2.0 * kPi * sigma, 2));
  EXPECT_NEAR(p.strehl / marechal, 1.0, 0.02) << p.strehl << " vs " << marechal;
  EXPECT_NEAR(p.strehl, exact, 2e-3);
  // Symmetric about the chief ray: the peak is at the zero angle, where the phasor mean is.
  EXPECT_NEAR(p.strehl, p.strehl_phasor, 1e-9);
}

TEST(PsfStrehl, PeakBetweenSamplesIsFound) {
  // A tilt of 0.37 lambda / D along x moves the peak between samples; the Strehl stays 1.
  const WavefrontResult w = synthetic(64, 2.0, [](glm::dvec2 u) { return 0.37 * u.x; });
  const Psf p = compute_psf(w, kEyeScale);
  EXPECT_NEAR(p.strehl, 1.0, 1e-6);
  EXPECT_LT(p.strehl_phasor, 0.8);  // the chief ray's point is off the peak
}

TEST(Mtf, ZeroOpdIsTheDiffractionLimit) {
  const Psf p = compute_psf(synthetic(128, 1.5, [](glm::dvec2) { return 0.0; }), kEyeScale);
  const double cutoff = sagittal_cutoff_cpd(p);
  EXPECT_NEAR(cutoff, 3.0 / 555e-6 * kPi / 180.0, 1e-9);  // D / lambda per radian, in cpd
  std::vector<double> freqs;
  for (double nu : {0.0, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.97}) freqs.push_back(nu * cutoff);
  const std::vector<MtfPoint> m = compute_mtf(p, freqs);
  for (size_t i = 0; i < freqs.size(); ++i) {
    const double expected = diffraction_limited_mtf(freqs[i] / cutoff);
    EXPECT_NEAR(m[i].tangential, expected, 0.01) << freqs[i];
    EXPECT_NEAR(m[i].sagittal, expected, 0.01) << freqs[i];
    // cycles per mm on the retina: cycles per radian over mm per radian.
    EXPECT_NEAR(m[i].sagittal_cyc_per_mm, freqs[i] * 180.0 / kPi / kEyeScale.sagittal_mm_per_rad, 1e-9);
  }
  EXPECT_DOUBLE_EQ(m[0].tangential, 1.0);
}

// The MTF at a shear of k pupil samples (frequency k delta / lambda) against the pupil function's
// autocorrelation summed directly over the samples: |sum P(u) conj P(u + k)| / M.
TEST(Mtf, EqualsTheDirectAutocorrelationOfThePupil) {
  const int grid = 48;
  const WavefrontResult w = synthetic(grid, 2.0, [](glm::dvec2 u) {
    return 0.25 * zernike(4, u.x, u.y) + 0.15 * zernike(7, u.x, u.y) + 0.1 * zernike(8, u.x, u.y);
  });
  const Psf p = compute_psf(w, kEyeScale);
  std::vector<std::complex<double>> pupil(static_cast<size_t>(grid) * grid, 0.0);
  for (size_t i = 0; i < w.pupil_points.size(); ++i) {
    const int ix = static_cast<int>(std::lround((w.pupil_points[i].x + 1.0) * grid / 2 - 0.5));
    const int iy = static_cast<int>(std::lround((w.pupil_points[i].y + 1.0) * grid / 2 - 0.5));
    pupil[static_cast<size_t>(iy) * grid + ix] = std::polar(1.0, 2.0 * kPi * w.opd_waves[i]);
  }
  auto autocorrelation = [&](int kx, int ky) {
    std::complex<double> sum(0.0);
    for (int y = 0; y + ky < grid; ++y)
      for (int x = 0; x + kx < grid; ++x)
        sum += pupil[static_cast<size_t>(y) * grid + x] * std::conj(pupil[static_cast<size_t>(y + ky) * grid + x + kx]);
    return std::abs(sum) / static_cast<double>(w.pupil_points.size());
  };
  const double delta = 2.0 * w.pupil_radius_mm / grid, lambda_mm = 555e-6;
  for (int k : {1, 5, 12, 24, 40}) {
    const double cpd = k * delta / lambda_mm * kPi / 180.0;
    const MtfPoint m = compute_mtf(p, {cpd}).front();
    EXPECT_NEAR(m.sagittal, autocorrelation(k, 0), 1e-9) << k;
    EXPECT_NEAR(m.tangential, autocorrelation(0, k), 1e-9) << k;
  }
}

TEST(MtfBadInput, FrequencyBeyondTheCutOffIsAnErrorNamingIt) {
  const Psf p = compute_psf(synthetic(64, 1.5, [](glm::dvec2) { return 0.0; }), kEyeScale);
  try {
    compute_mtf(p, {100.0});  // cut-off 94.3 cpd for 3 mm at 555 nm
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("94.3 cycles/deg"), std::string::npos) << e.what();
  }
}

TEST(PsfBadInput, TooCoarseAGridIsReported) {
  // 8 waves of defocus across a 16-sample pupil: neighbouring phases differ by more than pi/2.
  const Psf p = compute_psf(synthetic(16, 2.0, [](glm::dvec2 u) { return 8.0 * glm::dot(u, u); }), kEyeScale);
  EXPECT_GT(p.max_phase_step_rad, 0.5 * kPi);
  EXPECT_NE(p.warning.find("too coarse"), std::string::npos) << p.warning;
  EXPECT_THROW(compute_psf(synthetic(16, 2.0, [](glm::dvec2) { return 0.0; }), kEyeScale, {20}), OpticsError);
  EXPECT_THROW(compute_psf(WavefrontResult{}, kEyeScale), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// On the axis the retinal scale is the paraxial front focal length 1 / P (paraxial.h, independent
// of the chief-ray differences): the image of a distant point moves f tan(angle).
TEST(PsfEye, RetinalScaleOnAxisIsTheFocalLength) {
  EyeOptions e;
  e.model = "navarro";
  const Prescription p = make_eye(e);
  const RetinalScale s = retinal_scale(p, 0.0, std::numeric_limits<double>::infinity(), 0.0);
  EXPECT_NEAR(s.tangential_mm_per_rad / (1000.0 / paraxial_analysis(p).power_D), 1.0, 1e-3);
  EXPECT_EQ(s.sagittal_mm_per_rad, s.tangential_mm_per_rad);
}

// Navarro's eye at 20 degrees, 5 mm pupil: every number finite, the retinal scales near the
// 0.29 mm per degree of a 60 D eye, the tangential cut-off foreshortened by cos 20.
TEST(PsfEye, NavarroOffAxisIsFinite) {
  EyeOptions e;
  e.model = "navarro";
  const Prescription p = make_eye(e);
  WavefrontOptions o;
  o.field_deg = 20.0;
  o.pupil_radius_mm = 2.5;
  o.wavelength_nm = 555.0;
  o.grid = 128;
  const WavefrontResult w = trace_wavefront(p, o);
  const RetinalScale scale = retinal_scale(p, 20.0, o.object_distance_m, 555.0);
  EXPECT_NEAR(scale.tangential_mm_per_rad * kPi / 180.0, 0.29, 0.03);
  EXPECT_NEAR(scale.sagittal_mm_per_rad * kPi / 180.0, 0.29, 0.03);
  const Psf psf = compute_psf(w, scale);
  for (double v : {psf.strehl, psf.strehl_phasor, psf.ee50_um, psf.ee80_um, psf.sample_x_um, psf.sample_y_um})
    EXPECT_TRUE(std::isfinite(v) && v > 0.0);
  EXPECT_LT(psf.strehl, 1.0);
  EXPECT_LT(psf.ee50_um, psf.ee80_um);
  EXPECT_NEAR(tangential_cutoff_cpd(psf) / sagittal_cutoff_cpd(psf), std::cos(20.0 * kPi / 180.0), 1e-12);
  for (const MtfPoint& m : compute_mtf(psf, {5, 10, 20, 30, 40, 60})) {
    EXPECT_TRUE(m.tangential >= 0.0 && m.tangential <= 1.0);
    EXPECT_TRUE(m.sagittal >= 0.0 && m.sagittal <= 1.0);
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
