// The "sppm" integrator on scenes with known answers. Inside a closed, two-sided emitting
// diffuse sphere (radiance Le = 1, albedo a = 1/2) every estimator converges to
// Le (1 + a + ... + a^d) after d bounces; SPPM has no radius bias there, since the radiance is
// uniform and the part of a sphere of radius R within a 3-D distance r of a point on it has area
// exactly pi r^2 (Archimedes' cap, height r^2 / 2R), as the density estimate assumes. The
// radius follows the published reduction, the image does not depend on the thread count, and
// what sppm cannot do is refused with an error that names it.
#include <gtest/gtest.h>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "core/error.h"
#include "integrators/sppm_integrator.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string emitting_sphere(const std::string& integrator, const std::string& extra = "") {
  return fmt::format(
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 60\n"
      "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      "Sampler \"independent\" \"integer pixelsamples\" 27\nPixelFilter \"box\"\n"
      "Integrator {}\nWorldBegin\n{}"
      "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
      "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\nShape \"sphere\" \"float radius\" 2\n",
      integrator, extra);
}

const char* kSppm = "\"sppm\" \"float radius\" 0.1 \"integer photonsperiteration\" 4000";

struct Rendered {
  Image image;
  SppmIntegrator::PixelHistory history;
};

Rendered render(const std::string& text, int threads = 2, std::optional<IVec2> record = std::nullopt,
                const AdaptiveOptions* adaptive = nullptr) {
  SceneDescription desc = parse_scene_string(text, "sppm.pbrt", ".");
  RenderSetup s = build_render_setup(desc, {});
  auto* sppm = dynamic_cast<SppmIntegrator*>(s.integrator.get());
  EXPECT_NE(sppm, nullptr);
  if (sppm && record) sppm->record_pixel(*record);
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = threads;
  opts.adaptive = adaptive;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  return {s.film->image(), sppm ? sppm->history() : SppmIntegrator::PixelHistory{}};
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// 27 iterations: each iteration renders every pixel at the same four wavelengths (pbrt-v4's
// radical inverse in base 3), so the colour integral is a quadrature that is best after 3^k
// iterations (after 32 it is 0.8 % high at maxdepth 1, where no photon counts). Measured over six
// seeds, the image means differ from the series by +0.005 on average with a standard deviation
// of 0.006 (maxdepth 5; less at 1 and 3); the tolerance 0.03 is five of them, and half the
// 0.0625 by which one bounce more or less changes the answer at maxdepth 3. Before photons
// entered each grid bucket once, maxdepth 5 was 0.04 high.
TEST(SppmIntegrator, ClosedEmittingSphereGivesTheGeometricSeriesOfItsDepth) {
  const std::string p = kSppm;
  EXPECT_NEAR(test::image_mean(render(emitting_sphere(p + " \"integer maxdepth\" 1")).image), 1.5, 0.03);
  EXPECT_NEAR(test::image_mean(render(emitting_sphere(p + " \"integer maxdepth\" 3")).image), 1.875, 0.03);
  EXPECT_NEAR(test::image_mean(render(emitting_sphere(p)).image), 1.96875, 0.03);  // default 5
}

// Hachisuka and Jensen (2009), eqs. 8 and 11 with gamma = 2/3, recomputed here from the photon
// counts M the render recorded for one pixel: N_{i+1} = N_i + gamma M_i and
// r_{i+1}^2 = r_i^2 (N_i + gamma M_i) / (N_i + M_i), from N_0 = 0 and r_0 = "radius".
// The camera pass needs camera rays only, so an eye renders too: through the Navarro eye the
// closed sphere's uniform radiance reaches the image centre with weight 1 (lens cameras
// normalise relative illumination there), so the central pixels see the series as a pinhole's
// do; the edges see less (vignetting and lost rays), never more, and nothing is non-finite.
TEST(SppmIntegrator, RendersThroughAnEye) {
  std::string text = emitting_sphere(kSppm);
  text.replace(text.find("Camera \"perspective\" \"float fov\" 60"), 35, "Camera \"navarro\" \"float fov\" 30");
  const Image im = render(text).image;
  double centre = 0;
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x)
      for (int c = 0; c < 3; ++c) centre += im.at(x, y, c) / 48.0;
  EXPECT_NEAR(centre, 1.96875, 0.06);
  EXPECT_LT(test::image_mean(im), 1.96875 + 0.03);
  EXPECT_GT(test::image_mean(im), 0.5);
}

TEST(SppmIntegrator, RadiusShrinksByThePublishedRule) {
  const Rendered r =
      render(emitting_sphere("\"sppm\" \"float radius\" 0.5 \"integer photonsperiteration\" 4000"), 2, IVec2(7, 9));
  const auto& h = r.history;
  ASSERT_EQ(h.m.size(), 27u);
  double n = 0, r2 = double(0.5f) * double(0.5f);  // the parameter is read as a float
  uint64_t photons = 0;
  for (size_t i = 0; i < h.m.size(); ++i) {
    EXPECT_NEAR(h.n[i], n, 1e-9 * (1 + n)) << i;
    EXPECT_NEAR(h.radius[i] * h.radius[i], r2, 1e-9 * r2) << i;
    const double m = double(h.m[i]);
    if (m > 0) r2 *= (n + 2.0 / 3.0 * m) / (n + m);
    n += 2.0 / 3.0 * m;
    photons += h.m[i];
  }
  EXPECT_GT(photons, 300u);  // photons did land: the rule was exercised
  EXPECT_LT(r2, 0.5 * 0.5 * 0.5);
}

TEST(SppmIntegrator, SameSeedSameImageForOneAndTwoThreads) {
  const std::string text = emitting_sphere(fmt::format("{} \"integer seed\" 3", kSppm));
  const Image one = render(text, 1).image, two = render(text, 2).image;
  EXPECT_TRUE(one.pixels == two.pixels) << "images differ between 1 and 2 threads";
  const Image other = render(emitting_sphere(fmt::format("{} \"integer seed\" 4", kSppm)), 2).image;
  EXPECT_FALSE(one.pixels == other.pixels) << "the photons' seed has no effect";
}

TEST(SppmIntegrator, BadParametersAreNamedWithTheirPlace) {
  for (const char* bad : {"\"float radius\" 0", "\"float radius\" -1", "\"integer photonsperiteration\" -5",
                          "\"integer maxdepth\" -1", "\"integer seed\" -2"}) {
    const std::string e = error_of([&] { render(emitting_sphere(std::string("\"sppm\" ") + bad)); });
    const std::string name = std::string(bad).substr(std::string(bad).find(' ') + 1);
    EXPECT_NE(e.find("sppm.pbrt:6:"), std::string::npos) << e;
    EXPECT_NE(e.find(name.substr(0, name.find('"'))), std::string::npos) << bad << ": " << e;
  }
}

TEST(SppmIntegrator, RefusesWhatItDoesNotSupportByName) {
  const std::string media =
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.1 0.1]\n"
      "MediumInterface \"fog\" \"\"\n";
  std::string e = error_of([&] { render(emitting_sphere(kSppm, media)); });
  EXPECT_NE(e.find("participating media"), std::string::npos) << e;
  AdaptiveOptions adaptive;
  adaptive.max_spp = 27;
  e = error_of([&] { render(emitting_sphere(kSppm), 2, std::nullopt, &adaptive); });
  EXPECT_NE(e.find("--adaptive"), std::string::npos) << e;
  std::string spectral = emitting_sphere(kSppm);
  spectral.replace(spectral.find("Film \"rgb\""), 10, "Film \"spectral\"");
  e = error_of([&] { render(spectral); });
  EXPECT_NE(e.find("\"spectral\" film"), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
