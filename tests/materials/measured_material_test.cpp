// The "measured" material through the whole renderer:
//  - a quad of the committed GGX file (tests/data/measured) seen head-on in a uniform white sky
//    returns the sky times the BRDF's directional albedo at normal incidence, computed here by
//    quadrature of the analytic BRDF the file was made from (to 3 %, below);
//  - a missing "filename", a missing file and a broken file are errors naming the scene file,
//    the line, the parameter and what is wrong with the file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/chi2.h"
#include "../support/render_text.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::string kFile = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/measured/ggx-schlick.bsdf";

// Line 8 holds the material.
std::string scene(const std::string& material, int spp = 64) {
  return fmt::format(R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 2
Film "rgb" "integer xresolution" 8 "integer yresolution" 8
Sampler "independent" "integer pixelsamples" {}
Integrator "path" "integer maxdepth" 1
WorldBegin
LightSource "infinite" "spectrum L" [300 1  800 1]
Material {}
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]
)",
                     spp, material);
}

// The analytic BRDF of the file at normal incidence: F0(lambda) + ... integrated over the
// hemisphere with the cosine, at a wavelength (tests/data/measured/README.md).
double analytic_albedo_at_normal(double lambda) {
  const double a2 = 0.25, f0 = 0.25 + 0.6 * (lambda - 360.0) / 470.0;
  auto lambda_smith = [&](double c) { return (std::sqrt(1.0 + a2 * (1.0 - c * c) / (c * c)) - 1.0) / 2.0; };
  auto f_cos = [&](double ci, double) {
    // wo = +z; the half vector's cosine is sqrt((1 + ci) / 2).
    const double cm = std::sqrt((1.0 + ci) / 2.0), d = (a2 - 1.0) * cm * cm + 1.0;
    const double D = a2 / (kPiDouble * d * d), F = f0 + (1.0 - f0) * std::pow(1.0 - cm, 5.0);
    return F * D / (1.0 + lambda_smith(ci)) / 4.0;  // f cos_i with cos_o = 1, Lambda(wo) = 0
  };
  return chi2::integrate_rect(f_cos, 1e-6, 1.0, 0.0, 2.0 * kPiDouble, 80);
}

TEST(MeasuredMaterial, HeadOnInAWhiteSkyReturnsTheAlbedo) {
  const Image img =
      test::render_text(scene("\"measured\" \"string filename\" \"" + kFile + "\"", 256), "measured.pbrt");
  // A white diffuse quad (albedo exactly 1 at every wavelength) gives the film's response to the
  // sky; each channel's ratio is the albedo weighted by that channel's response. The albedo
  // rises almost linearly with lambda (0.25 at 450 nm, 0.34 at 550, 0.38 at 600), so the mean
  // of the three ratios is the albedo near the middle of the visible range: compared with the
  // albedo's mean over 400-700 nm within 3 % (measured: 2.3 %; a wrong f at normal incidence,
  // e.g. without the Fresnel's wavelength dependence or with sigma misread, is off by far more).
  const Image white = test::render_text(scene("\"diffuse\" \"spectrum reflectance\" [300 1  800 1]", 16), "white.pbrt");
  double ref = 0.0;
  for (double l = 400.0; l <= 700.0; l += 10.0) ref += analytic_albedo_at_normal(l) / 31.0;
  double mean = 0.0;
  for (int c = 0; c < 3; ++c) mean += test::channel_mean(img, c) / test::channel_mean(white, c) / 3.0;
  EXPECT_NEAR(mean, ref, 0.03 * ref);
  // Redder wavelengths reflect more (F0 rises with lambda).
  EXPECT_GT(test::channel_mean(img, 0), test::channel_mean(img, 2));
  RecordProperty("albedo", fmt::format("{:.4f} (analytic {:.4f})", mean, ref));
}

std::string error_of(const std::string& material) {
  try {
    test::render_text(scene(material, 1), "measured.pbrt");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MeasuredMaterial, BadFilesNameTheSceneLineParameterAndProblem) {
  std::string e = error_of("\"measured\"");
  EXPECT_TRUE(has(e, "measured.pbrt:8:") && has(e, "\"filename\"") && has(e, "required")) << e;
  e = error_of("\"measured\" \"string filename\" \"no-such.bsdf\"");
  EXPECT_TRUE(has(e, "measured.pbrt:8:") && has(e, "no-such.bsdf") && has(e, "no such file")) << e;

  test::TempDir dir("measured-material");
  const std::string bytes = test::read_text(kFile);
  const std::string truncated = dir.file("truncated.bsdf");
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  e = error_of("\"measured\" \"string filename\" \"" + truncated + "\"");
  EXPECT_TRUE(has(e, "measured.pbrt:8:") && has(e, "\"filename\"") && has(e, "truncated.bsdf") && has(e, "truncated:"))
      << e;
  const std::string png = dir.file("image.bsdf");
  std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\n and more bytes than a header";
  e = error_of("\"measured\" \"string filename\" \"" + png + "\"");
  EXPECT_TRUE(has(e, "measured.pbrt:8:") && has(e, "not a tensor file")) << e;
  // pbrt-v4's other materials' parameters are not the measured material's.
  e = error_of("\"measured\" \"string filename\" \"" + kFile + "\" \"float roughness\" 0.1");
  EXPECT_TRUE(has(e, "measured.pbrt:8:") && has(e, "roughness")) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
