// The volumetric path tracer against analytic answers, each a statistical test at 5 standard
// errors (pixels are independent: the "independent" sampler and a box filter; the standard
// error comes from the spread of pixels that share one expected value):
//  - Beer-Lambert: a chromatic absorber (sigma_a a step function of wavelength) in front of a
//    uniform sky passes exp(-sigma_a d) per wavelength bucket of a spectral film;
//  - an emissive absorber glows Le (1 - exp(-sigma_a d)), Le read as a light's emission;
//  - the white furnace: a sphere of chromatic, anisotropic, lossless scattering medium under a
//    uniform sky (or inside a uniformly emitting enclosure, the camera also in fog) looks
//    exactly like its surroundings. The enclosure is lit through next-event estimation and
//    phase sampling at once: a wrong MIS weight (say, without the shadow ray's transmittance)
//    breaks the equality;
//  - with absorption (albedo < 1) the sphere is darker: energy never grows;
//  - wavelengths a medium does not touch (sigma_t = 0) pass unchanged, also in a medium with
//    no boundary, and no estimate is NaN or infinite;
//  - a point light in absorbing fog: the exact shadow-ray transmittance times the camera ray's;
//  - the eye camera's rays leave into the camera's medium.
// Scenes without media render with "path" (the same code): tests/integrators/default_integrator_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "../support/volpath_scenes.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::ball;
using test::kSpectralFilm;
using test::kStep;
using test::kStepSpectrum;
using test::narrow_view;
using Stats = test::VolpathStats;

Stats render(const std::string& text) { return test::render_volpath_stats(text, "volpath.pbrt"); }

TEST(VolPathIntegrator, AbsorberPassesBeerLambertPerWavelength) {
  const std::string sky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  const std::string medium = "MakeNamedMedium \"ink\" \"string type\" \"homogeneous\" \"spectrum sigma_a\" " +
                             kStepSpectrum + " \"rgb sigma_s\" [0 0 0]\n";
  const Stats open = render(narrow_view(kSpectralFilm, 4) + medium + "WorldBegin\n" + sky);
  const Stats slab = render(narrow_view(kSpectralFilm, 64) + medium + "WorldBegin\n" + sky + ball("ink", "", 0.5f));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;  // R, G, B, then the buckets
    const double expected = open.mean[c] * std::exp(-kStep[b] * 1.0);
    EXPECT_NEAR(slab.mean[c], expected, 5 * slab.se[c] + 1e-6) << "bucket " << b;
    EXPECT_LT(slab.se[c], 0.05 * expected);  // the test can tell exp(-sigma d) from its neighbours
  }
}

// sigma_a is 0 below 500 nm: those wavelengths neither absorb nor emit, and a hero wavelength
// there samples no collision, so the emission of the others must come from the samples whose
// hero does collide, weighted by pbrt-v4's r_e (weighting by r_u alone loses about a quarter).
TEST(VolPathIntegrator, EmissiveAbsorberGlowsLeTimesOneMinusTransmittance) {
  const std::string medium =
      "MakeNamedMedium \"glow\" \"string type\" \"homogeneous\" \"spectrum sigma_a\" [400 0 499.99 0 500.01 1.5 "
      "599.99 1.5 600.01 3 700 3] \"rgb sigma_s\" [0 0 0] \"rgb Le\" [1 1 1] \"float Lescale\" 2\n";
  const double sigma[3] = {0.0, 1.5, 3.0};
  // The medium's Le is read as a light's emission: the same spectrum as a sky of that RGB.
  const Stats sky = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n");
  const Stats glow = render(narrow_view(kSpectralFilm, 64) + medium + "WorldBegin\n" + ball("glow", "", 0.5f));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    const double expected = 2.0 * sky.mean[c] * (1.0 - std::exp(-sigma[b] * 1.0));
    EXPECT_NEAR(glow.mean[c], expected, 5 * glow.se[c] + 1e-6) << "bucket " << b;
  }
}

// A 16x16 view of a unit sphere of medium from 4 units, most pixels on the sphere.
std::string furnace_view(const std::string& camera_medium, int spp) {
  return fmt::format(R"(MediumInterface "" "{}"
LookAt 0 0 4  0 0 0  0 1 0
Camera "perspective" "float fov" 30
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 1000
)",
                     camera_medium, spp);
}

// Lossless (albedo 1) when sigma_a is 0, at every wavelength: sigma_s is chromatic.
std::string cloud(double sigma_a) {
  return fmt::format(
      "MakeNamedMedium \"cloud\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [{0} {0} {0}] "
      "\"rgb sigma_s\" [0.5 1 2] \"float g\" 0.6\n",
      sigma_a);
}

TEST(VolPathIntegrator, WhiteFurnaceScatteringSphereVanishesUnderAUniformSky) {
  const std::string sky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  const Stats open = render(furnace_view("", 1) + "WorldBegin\n" + sky);
  const Stats cloudy = render(furnace_view("", 64) + cloud(0) + "WorldBegin\n" + sky + ball("cloud", "", 1.f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloudy.mean[c], open.mean[c], 5 * cloudy.se[c] + 1e-6) << "channel " << c;
}

TEST(VolPathIntegrator, AbsorptionOnlyDarkensEnergyNeverGrows) {
  const std::string sky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  const Stats open = render(furnace_view("", 1) + "WorldBegin\n" + sky);
  const Stats cloudy = render(furnace_view("", 64) + cloud(0.3) + "WorldBegin\n" + sky + ball("cloud", "", 1.f));
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(cloudy.mean[c], open.mean[c] - 5 * cloudy.se[c]) << "channel " << c;
    EXPECT_GT(cloudy.mean[c], 0.3 * open.mean[c]) << "channel " << c;
  }
}

// A black sphere of radius 6 emitting radiance 1 inwards encloses everything: the radiance at
// every point in every direction is 1 when nothing absorbs. Light reaches the cloud by light
// sampling and by phase-sampled rays hitting the wall, weighted by MIS.
std::string enclosure(const std::string& media) {
  return fmt::format(R"(AttributeBegin
 MediumInterface "{0}" "{0}"
 ReverseOrientation
 AreaLightSource "diffuse" "rgb L" [1 1 1]
 Material "diffuse" "rgb reflectance" [0 0 0]
 Shape "sphere" "float radius" 6
AttributeEnd
)",
                     media);
}

TEST(VolPathIntegrator, WhiteFurnaceInsideAnEmittingEnclosureWithMisBetweenLightAndPhaseSampling) {
  const Stats open = render(furnace_view("", 1) + "WorldBegin\n" + enclosure(""));
  const Stats cloudy =
      render(furnace_view("", 64) + cloud(0) + "WorldBegin\n" + enclosure("") + ball("cloud", "", 1.f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloudy.mean[c], open.mean[c], 5 * cloudy.se[c] + 1e-6) << "channel " << c;
}

TEST(VolPathIntegrator, WhiteFurnaceWithTheCameraInFog) {
  const std::string fog =
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [0.3 0.2 0.1] "
      "\"float g\" -0.3\n";
  const Stats open = render(furnace_view("", 1) + "WorldBegin\n" + enclosure(""));
  const Stats foggy =
      render(furnace_view("fog", 64) + fog + cloud(0) + "WorldBegin\n" + enclosure("fog") + ball("cloud", "fog", 1.f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(foggy.mean[c], open.mean[c], 5 * foggy.se[c] + 1e-6) << "channel " << c;
}

// sigma_t is zero below 500 nm: those wavelengths see vacuum, including rays that leave for
// infinity inside the unbounded fog around the camera (no NaN from 0 * inf).
TEST(VolPathIntegrator, WavelengthsWithoutExtinctionPassUnchangedThroughUnboundedFog) {
  const std::string fog =
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"spectrum sigma_a\" [400 0 499.99 0 500.01 0.5 700 "
      "0.5] \"spectrum sigma_s\" [400 0 499.99 0 500.01 1 700 1]\n";
  const std::string sky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  std::string view = narrow_view(kSpectralFilm, 64);
  const Stats open = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\n" + sky);
  const Stats foggy = render("MediumInterface \"\" \"fog\"\n" + view + fog + "WorldBegin\n" + sky);
  EXPECT_NEAR(foggy.mean[3], open.mean[3], 5 * foggy.se[3] + 1e-6);
  for (int c = 4; c < 6; ++c) EXPECT_LT(foggy.mean[c], open.mean[c]) << "bucket " << c - 3;
}

// A point light (a delta light: light sampling alone, weight 1) 1 unit above a diffuse disk, seen
// from 2 units away, all in absorbing fog: the radiance is the clear scene's times
// exp(-sigma (1 + 2)) per wavelength, the shadow ray's transmittance (exact) times the camera
// ray's (sampled).
TEST(VolPathIntegrator, PointLightInAbsorbingFogIsAttenuatedAlongBothSegments) {
  const std::string fog =
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"spectrum sigma_a\" [400 0.1 499.99 0.1 500.01 0.3 "
      "599.99 0.3 600.01 0.6 700 0.6] \"rgb sigma_s\" [0 0 0]\n";
  const double sigma[3] = {0.1, 0.3, 0.6};
  auto scene = [&](const std::string& medium, int spp) {
    return fog + "MediumInterface \"\" \"" + medium + "\"\n" +
           fmt::format(R"(LookAt 1.41421356 0 1.41421356  0 0 0  0 1 0
Camera "perspective" "float fov" 0.2
{}
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 5
WorldBegin
LightSource "point" "point3 from" [0 0 1] "rgb I" [1 1 1]
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "disk" "float radius" 1
)",
                       kSpectralFilm, spp);
  };
  const Stats clear = render(scene("", 4));
  const Stats foggy = render(scene("fog", 64));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    ASSERT_GT(clear.mean[c], 0.0);
    const double expected = clear.mean[c] * std::exp(-sigma[b] * 3.0);
    EXPECT_NEAR(foggy.mean[c], expected, 5 * foggy.se[c] + 1e-6) << "bucket " << b;
  }
}

// The eye's rays leave its cornea into the medium the camera sits in: an absorber of 0.1 per
// unit length filling a sphere of radius 10 around the eye passes exp(-1) of a uniform sky (the
// eye's own 24 mm change it by 0.24 %, well inside the tolerance). The scene has no Camera
// directive (the eye comes from the command line): the medium current at WorldBegin is used.
TEST(VolPathIntegrator, EyeCameraRaysLeaveIntoTheCameraMedium) {
  const std::string head = R"(Film "rgb" "integer xresolution" 8 "integer yresolution" 8
Sampler "independent" "integer pixelsamples" 64
PixelFilter "box"
MakeNamedMedium "haze" "string type" "homogeneous" "rgb sigma_a" [0.1 0.1 0.1] "rgb sigma_s" [0 0 0]
)";
  auto render_eye = [&](const std::string& text) {
    RenderOverrides o;
    o.camera = SceneEntity{"navarro", ParameterList(), SourceLoc{}};
    RenderSetup s = build_render_setup(parse_scene_string(text, "eye.pbrt", "."), o);
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
    EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
    const Image img = s.film->image();
    double sum = 0;
    for (float v : img.pixels) sum += v;
    return sum / img.pixels.size();
  };
  const std::string world = "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  const double clear = render_eye(head + world);
  const double hazy = render_eye(head + "MediumInterface \"\" \"haze\"\n" + world + ball("haze", "", 10.f));
  ASSERT_GT(clear, 0.0);
  // 4096 samples, each 0 or the clear value (a grey absorber): standard error 2 %; 5 of them.
  EXPECT_NEAR(hazy / clear, std::exp(-1.0), 0.1 * std::exp(-1.0));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
