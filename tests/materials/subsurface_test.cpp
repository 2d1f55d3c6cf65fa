// The "subsurface" material's pieces (pbrt-v4's photon beam diffusion BSSRDF):
//  - the beam-diffusion profile and the table's effective albedo against an independent
//    numerical evaluation of the same published formulas (tests/data/subsurface/pbd_reference.py:
//    double precision, 2e5-point quadrature, Fresnel moments integrated instead of fitted);
//  - the radius sampling against its claimed density (chi-square) and that density's
//    normalisation;
//  - SubsurfaceFromDiffuse: the coefficients it fits reproduce the reflectance asked for;
//  - the named measured media against the published numbers (Jensen et al. 2001);
//  - bad parameters: errors naming file, line and parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "../support/chi2.h"
#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "core/catmull_rom.h"
#include "core/measured_media.h"
#include "materials/bssrdf_table.h"
#include "materials/tabulated_bssrdf.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::string kReference = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/subsurface/pbd_reference.txt";

std::vector<std::vector<std::string>> reference_lines(const std::string& kind) {
  std::ifstream in(kReference);
  EXPECT_TRUE(in) << kReference;
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ss(line);
    std::vector<std::string> row;
    for (std::string w; ss >> w;) row.push_back(w);
    if (!row.empty() && row[0] == kind) rows.push_back(row);
  }
  return rows;
}

// The tables the tests share (each takes ~50 ms to compute).
const BSSRDFTable& table(float g, float eta) {
  static std::map<std::pair<float, float>, BSSRDFTable> cache;
  auto it = cache.find({g, eta});
  if (it == cache.end()) it = cache.emplace(std::pair{g, eta}, compute_beam_diffusion_table(g, eta)).first;
  return it->second;
}

// 5-point Gauss-Legendre on [a, b]: exact for the cubic segments of a Catmull-Rom spline.
template <typename F>
double gauss5(const F& f, double a, double b) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  double s = 0;
  for (int i = 0; i < 5; ++i) s += w[i] * f(0.5 * (a + b) + 0.5 * (b - a) * x[i]);
  return 0.5 * (b - a) * s;
}

// The integral of 2 pi r f(r) over [0, table's last radius / sigma_t], segment by segment.
template <typename F>
double radial_integral(const BSSRDFTable& t, float sigma_t, const F& f) {
  double sum = 0;
  for (size_t i = 0; i + 1 < t.radius_samples.size(); ++i)
    sum += gauss5([&](double r) { return 2 * kPi * r * f(float(r)); }, t.radius_samples[i] / sigma_t,
                  t.radius_samples[i + 1] / sigma_t);
  return sum;
}

// The C++ evaluation uses 100 stratified depth samples and pbrt-v4's Fresnel-moment fits; the
// reference 2e5 samples and exact moments. At optical radii >= 0.05 the quadrature error of
// 100 samples stays below 2% (both terms' integrands are smooth there); the fits differ from
// the integrals by < 0.5% (FresnelMoment1(1.33): 0.2365 fitted, 0.2360 integrated).
TEST(BeamDiffusion, ProfileMatchesAnIndependentQuadratureOfThePublishedFormulas) {
  const auto rows = reference_lines("profile");
  ASSERT_EQ(rows.size(), 24u);
  for (const auto& row : rows) {
    const float ss = std::stof(row[1]), sa = std::stof(row[2]), g = std::stof(row[3]), eta = std::stof(row[4]),
                r = std::stof(row[5]);
    const double ref_ss = std::stod(row[6]), ref_ms = std::stod(row[7]);
    const double got_ss = beam_diffusion_ss(ss, sa, g, eta, r), got_ms = beam_diffusion_ms(ss, sa, g, eta, r);
    const std::string where = fmt::format("sigma_s {} sigma_a {} g {} eta {} r {}", ss, sa, g, eta, r);
    EXPECT_NEAR(got_ms, ref_ms, 0.02 * ref_ms) << where;
    // Single scattering far out is negligible (< 1e-4 of multiple scattering) and decays by
    // exp(-sigma_t d) over the samples, where relative accuracy means nothing.
    if (ref_ss > 1e-4 * ref_ms) EXPECT_NEAR(got_ss, ref_ss, 0.02 * ref_ss) << where;
    EXPECT_LT(std::abs(got_ss - ref_ss), 0.02 * (ref_ss + ref_ms)) << where;
  }
}

// rho_eff (the integral of the tabulated profile, the total diffuse reflectance of the
// half-space) against the reference's integral of the same profile at 600 radii with 2e4
// depth samples. The table resolves small radii with 100 depth samples only, so the two may
// differ by up to 2% at low albedo (where the near-field single scattering dominates).
TEST(BeamDiffusion, TableAlbedoIsTheTotalDiffuseReflectanceIntegral) {
  const auto rows = reference_lines("rho_eff");
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& row : rows) {
    const float g = std::stof(row[1]), eta = std::stof(row[2]);
    const int i = std::stoi(row[3]);
    const double ref = std::stod(row[4]);
    const BSSRDFTable& t = table(g, eta);
    EXPECT_NEAR(t.rho_eff[size_t(i)], ref, 0.02 * ref) << "g " << g << " eta " << eta << " rho " << t.rho_samples[i];
    // And the table's CDF ends where its integral does.
    EXPECT_FLOAT_EQ(t.profile_cdf[size_t(i) * t.radius_samples.size() + t.radius_samples.size() - 1], t.rho_eff[i]);
  }
  // The albedo grid is pbrt-v4's: 0 and 1 at the ends.
  EXPECT_EQ(table(0.f, 1.33f).rho_samples.front(), 0.f);
  EXPECT_FLOAT_EQ(table(0.f, 1.33f).rho_samples.back(), 1.f);
}

TabulatedBSSRDF test_bssrdf(const BSSRDFTable& t) {
  SampledSpectrum sa, ss;
  const float a[4] = {0.5f, 0.05f, 1.f, 0.2f}, s[4] = {4.f, 2.f, 1.f, 6.f};
  for (int i = 0; i < 4; ++i) sa[i] = a[i], ss[i] = s[i];
  return TabulatedBSSRDF(Vec3(0.f), Vec3(0.f, 0.f, 1.f), 1.33f, sa, ss, &t);
}

TEST(TabulatedBSSRDF, RadiusDensityIsNormalisedAndProportionalToTheProfile) {
  const BSSRDFTable& t = table(0.f, 1.33f);
  const TabulatedBSSRDF b = test_bssrdf(t);
  const float sigma_t[4] = {4.5f, 2.05f, 2.f, 6.2f};
  for (int i = 0; i < 4; ++i) {
    // Exact spline arithmetic makes this 1 up to float rounding.
    EXPECT_NEAR(radial_integral(t, sigma_t[i], [&](float r) { return b.pdf_sr(r)[i]; }), 1.0, 1e-3) << i;
    // pdf = Sr / (integral of Sr): the ratio is the same constant everywhere.
    const double total = radial_integral(t, sigma_t[i], [&](float r) { return b.sr(r)[i]; });
    for (float r : {0.01f, 0.1f, 0.4f}) EXPECT_NEAR(b.pdf_sr(r)[i], b.sr(r)[i] / total, 1e-4 * b.sr(r)[i] / total);
  }
}

// 2e5 radii from sample_sr binned between the table's radius nodes (at the hero wavelength's
// sigma_t) against the integral of pdf_sr over each bin. A correct sampler fails this with
// probability 1e-3 (the significance); the seed is fixed, so the outcome is deterministic.
TEST(TabulatedBSSRDF, SampledRadiiFollowTheProfileChiSquare) {
  const BSSRDFTable& t = table(0.3f, 1.5f);
  const TabulatedBSSRDF b = test_bssrdf(t);
  const float sigma_t0 = 4.5f;
  const size_t bins = t.radius_samples.size() - 1;
  std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(0.f, 1.f);
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const std::optional<float> r = b.sample_sr(uni(rng));
    ASSERT_TRUE(r && std::isfinite(*r) && *r >= 0.f);
    const float ro = *r * sigma_t0;
    const auto it = std::upper_bound(t.radius_samples.begin(), t.radius_samples.end(), ro);
    const size_t bin = std::min(size_t(std::max<ptrdiff_t>(it - t.radius_samples.begin() - 1, 0)), bins - 1);
    observed[bin] += 1;
  }
  for (size_t i = 0; i < bins; ++i)
    expected[i] = n * gauss5([&](double r) { return 2 * kPi * r * b.pdf_sr(float(r))[0]; },
                             t.radius_samples[i] / sigma_t0, t.radius_samples[i + 1] / sigma_t0);
  const chi2::Result res = chi2::pearson(observed, expected);
  EXPECT_TRUE(res.passes(1e-3)) << res.summary();
}

// An exit point's density over a plane through the entry (normal +z): only the probes along
// the normal (probability 1/2) meet it, at the sampled radius, so its integral over the plane
// is 1/2 of the radius density's mass inside the probe's reach (the 99.9th percentile).
TEST(TabulatedBSSRDF, ExitDensityOverThePlaneOfEntryIsHalfTheRadiusDensity) {
  const BSSRDFTable& t = table(0.f, 1.33f);
  const TabulatedBSSRDF b = test_bssrdf(t);
  const double plane = radial_integral(t, 4.5f, [&](float r) { return b.pdf_sp(Vec3(r, 0.f, 0.f), Vec3(0, 0, 1))[0]; });
  EXPECT_NEAR(plane, 0.5, 1e-3);
  // A plane perpendicular to the entry's (x = 0, normal +x) is met by the probes along x.
  const double side = radial_integral(t, 4.5f, [&](float r) { return b.pdf_sp(Vec3(0.f, r, 0.f), Vec3(1, 0, 0))[0]; });
  EXPECT_NEAR(side, 0.25, 1e-3);
}

// SubsurfaceFromDiffuse inverts the table: the coefficients it fits, put back into the BSSRDF,
// give a profile whose integral over the plane (the diffuse reflectance) is the one asked for.
// A reflectance above the table's albedo-1 value (0.948 for g 0.5, eta 1.5) has no medium: it
// saturates there (pbrt-v4's InvertCatmullRom clamps to the last node).
TEST(SubsurfaceFromDiffuse, FittedCoefficientsReproduceTheReflectance) {
  for (auto [g, eta] : {std::pair{0.f, 1.33f}, std::pair{0.5f, 1.5f}}) {
    const BSSRDFTable& t = table(g, eta);
    for (float refl : {0.02f, 0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 0.95f, 0.99f}) {
      SampledSpectrum rho_eff(refl), mfp, sa, ss;
      const float m[4] = {0.5f, 0.1f, 2.f, 1.f};
      for (int i = 0; i < 4; ++i) mfp[i] = m[i];
      subsurface_from_diffuse(t, rho_eff, mfp, &sa, &ss);
      const TabulatedBSSRDF b(Vec3(0.f), Vec3(0, 0, 1), eta, sa, ss, &t);
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(1.f / (sa[i] + ss[i]), m[i], 1e-5f * m[i]);
        const double r = radial_integral(t, sa[i] + ss[i], [&](float x) { return b.sr(x)[i]; });
        EXPECT_NEAR(r, std::min(refl, t.rho_eff.back()), 1e-3) << "g " << g << " eta " << eta << " mfp " << m[i];
      }
    }
  }
}

// Jensen, Marschner, Levoy, Hanrahan, "A Practical Model for Subsurface Light Transport",
// SIGGRAPH 2001, Figure 5: sigma'_s and sigma_a [mm^-1] for R, G, B, typed from the paper.
TEST(MeasuredMedia, JensenDataEqualThePublishedNumbers) {
  struct Row {
    const char* name;
    float s[3], a[3];
  };
  const Row published[] = {{"Skin1", {0.74f, 0.88f, 1.01f}, {0.032f, 0.17f, 0.48f}},
                           {"Skin2", {1.09f, 1.59f, 1.79f}, {0.013f, 0.070f, 0.145f}},
                           {"Marble", {2.19f, 2.62f, 3.00f}, {0.0021f, 0.0041f, 0.0071f}},
                           {"Ketchup", {0.18f, 0.07f, 0.03f}, {0.061f, 0.97f, 1.45f}},
                           {"Wholemilk", {2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}}};
  for (const Row& row : published) {
    const MeasuredMedium* m = find_measured_medium(row.name);
    ASSERT_NE(m, nullptr) << row.name;
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(m->sigma_prime_s[c], row.s[c]) << row.name;
      EXPECT_EQ(m->sigma_a[c], row.a[c]) << row.name;
    }
  }
  EXPECT_EQ(find_measured_medium("skin1"), nullptr);  // names are case-sensitive, as in pbrt-v4
  EXPECT_EQ(measured_medium_names().size(), 47u);     // pbrt-v4's table: 12 + 35
}

std::string error_of(const std::string& material) {
  try {
    test::render_text(fmt::format(R"(Film "rgb" "integer xresolution" 2 "integer yresolution" 2
Sampler "independent" "integer pixelsamples" 1
WorldBegin
Material "subsurface" {}
Shape "sphere")",
                                  material),
                      "sss.pbrt");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SubsurfaceMaterial, BadParametersNameFileLineAndParameter) {
  for (auto [bad, param] :
       {std::pair{R"("string name" "Skin9")", "name"}, std::pair{R"("rgb sigma_a" [1 1 1])", "sigma_a"},
        std::pair{R"("rgb sigma_s" [1 1 1])", "sigma_s"}, std::pair{R"("float eta" 0)", "eta"},
        std::pair{R"("float g" 1)", "g"}, std::pair{R"("float scale" -1)", "scale"},
        std::pair{R"("rgb sigma_a" [1 -1 1] "rgb sigma_s" [1 1 1])", "sigma_a"},
        std::pair{R"("rgb sigma_a" [1 1 1] "spectrum sigma_s" [400 1 700 -2])", "sigma_s"},
        std::pair{R"("rgb reflectance" [0.5 0.5 0.5] "rgb mfp" [1 0 1])", "mfp"}}) {
    const std::string e = error_of(bad);
    EXPECT_NE(e.find("sss.pbrt:4"), std::string::npos) << bad << ": " << e;
    EXPECT_NE(e.find(param), std::string::npos) << bad << ": " << e;
  }
  EXPECT_EQ(error_of(R"("string name" "Skin1" "float scale" 10)"), "");
  EXPECT_EQ(error_of(R"("rgb reflectance" [0.5 0.5 0.5] "rgb mfp" [1 2 3])"), "");
  EXPECT_EQ(error_of(""), "");  // pbrt-v4's default coefficients
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
