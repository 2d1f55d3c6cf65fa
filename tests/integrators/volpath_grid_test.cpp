// The volumetric path tracer through heterogeneous media (delta tracking against majorant grids,
// ratio-tracked shadow rays, pbrt-v4's spectral MIS at null collisions), against analytic
// answers, each a statistical test at 5 standard errors (independent sampler, box filter: pixels
// with one expected value are independent samples of it):
//  - a constant-density "uniformgrid" renders as the homogeneous medium of the same sigma
//    (a furnace-free scene with absorption, chromatic scattering, an area light);
//  - a chromatic absorber grid of constant density passes exp(-sigma_a d) per wavelength bucket,
//    and glows Le (1 - exp(-sigma_a d)) when it emits;
//  - a constant chromatic rgbgrid passes per bucket what the homogeneous medium of its RGB does;
//  - a linear density ramp along the ray passes exp(-sigma_a integral of density): the DDA and
//    the trilinear lookups together (the ramp is exact between the outer sample centres);
//  - a point light in an absorbing grid fog: the shadow ray's ratio-tracked transmittance times
//    the camera ray's, per wavelength (a wrong MIS ratio at null collisions breaks it);
//  - the white furnace: a sphere of heterogeneous, lossless, chromatic grid medium under a
//    uniform sky (and inside an emitting enclosure: light and phase sampling with MIS) looks
//    exactly like its surroundings;
//  - the cloud medium under a uniform sky, lossless: the same.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

Stats render(const std::string& text) { return test::render_volpath_stats(text, "volpath_grid.pbrt"); }

std::string floats(const std::vector<float>& v) {
  std::string s = "[";
  for (float x : v) s += fmt::format(" {}", x);
  return s + " ]";
}

// (Defined after WorldBegin: before it, the CTM is the camera's LookAt, which pbrt-v4 applies to
// a MakeNamedMedium there.)
// A grid medium over [-2, 2]^3 with n^3 samples of f(x, y, z) (sample centres, medium space).
template <typename F>
std::string grid_medium(const std::string& name, int n, F f, const std::string& coefficients) {
  std::vector<float> d;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto c = [&](int a) { return -2.f + 4.f * (a + 0.5f) / n; };
        d.push_back(f(c(i), c(j), c(k)));
      }
  return fmt::format(
      "MakeNamedMedium \"{}\" \"string type\" \"uniformgrid\" \"integer nx\" {} \"integer ny\" {} \"integer nz\" {} "
      "\"point3 p0\" [-2 -2 -2] \"point3 p1\" [2 2 2] \"float density\" {} {}\n",
      name, n, n, n, floats(d), coefficients);
}

const std::string kSky = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";

// The sphere of radius 0.5 lies where a 4^3 grid over [-2, 2]^3 is constant (the fading outer
// half cells start at |x| = 1.5).
TEST(VolPathGrid, ConstantDensityAbsorberPassesBeerLambertPerWavelength) {
  const std::string medium = grid_medium(
      "ink", 4, [](float, float, float) { return 2.f; },
      "\"spectrum sigma_a\" " + kStepSpectrum + " \"rgb sigma_s\" [0 0 0] \"float scale\" 0.5");
  const Stats open = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\n" + kSky);
  const Stats slab = render(narrow_view(kSpectralFilm, 64) + "WorldBegin\n" + medium + kSky + ball("ink", "", 0.5f));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    const double expected = open.mean[c] * std::exp(-kStep[b] * 1.0);  // density 2 x scale 0.5, d = 1
    EXPECT_NEAR(slab.mean[c], expected, 5 * slab.se[c] + 1e-6) << "bucket " << b;
    EXPECT_LT(slab.se[c], 0.05 * expected);
  }
}

// An emissive absorber grid (constant density 1, Le read as a light's emission, an Lescale grid
// of 2s: without one, pbrt-v4's single Lescale sample fades towards the faces): it glows
// Le (1 - exp(-sigma_a d)) per wavelength. sigma_a is 0 below 500 nm: a hero there samples no
// collision and the emission of the others comes through pbrt-v4's r_e weights at the
// tentative collisions of the samples whose hero does collide.
TEST(VolPathGrid, EmissiveGridGlowsLeTimesOneMinusTransmittance) {
  const std::string medium = grid_medium(
      "glow", 4, [](float, float, float) { return 1.f; },
      "\"spectrum sigma_a\" [400 0 499.99 0 500.01 1.5 599.99 1.5 600.01 3 700 3] \"rgb sigma_s\" [0 0 0] "
      "\"rgb Le\" [1 1 1] \"float Lescale\" " +
          floats(std::vector<float>(64, 2.f)));
  const double sigma[3] = {0.0, 1.5, 3.0};
  const Stats sky = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\n" + kSky);
  const Stats glow = render(narrow_view(kSpectralFilm, 64) + "WorldBegin\n" + medium + ball("glow", "", 0.5f));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    const double expected = 2.0 * sky.mean[c] * (1.0 - std::exp(-sigma[b] * 1.0));
    EXPECT_NEAR(glow.mean[c], expected, 5 * glow.se[c] + 1e-6) << "bucket " << b;
  }
  EXPECT_GT(glow.mean[5], 0.5 * sky.mean[5]);  // it does glow
}

// density 1 + 0.75 (z + 2) along the view (z): over z in [-0.5, 0.5] its integral is
// 1 + 0.75 * 2 = 2.5. An 8^3 grid over [-2, 2]^3 reproduces it exactly for |z| < 1.75.
TEST(VolPathGrid, LinearRampAlongTheRayPassesExpOfTheIntegral) {
  const std::string medium = grid_medium(
      "ramp", 8, [](float, float, float z) { return 1.f + 0.75f * (z + 2.f); },
      "\"spectrum sigma_a\" [400 0.2 499.99 0.2 500.01 0.6 599.99 0.6 600.01 1.2 700 1.2] \"rgb sigma_s\" [0 0 0]");
  const double sigma[3] = {0.2, 0.6, 1.2};
  const Stats open = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\n" + kSky);
  const Stats ramp = render(narrow_view(kSpectralFilm, 64) + "WorldBegin\n" + medium + kSky + ball("ramp", "", 0.5f));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    const double expected = open.mean[c] * std::exp(-sigma[b] * 2.5);
    EXPECT_NEAR(ramp.mean[c], expected, 5 * ramp.se[c] + 1e-6) << "bucket " << b;
    EXPECT_LT(ramp.se[c], 0.05 * expected);  // fine enough to tell 2.5 from 2.4 or 2.6 in the exponent
  }
}

// A chromatic rgbgrid absorber of constant RGB passes, per wavelength bucket, what the
// homogeneous medium of the same RGB passes (its exact Beer-Lambert path, tested against
// exp(-sigma d) in volpath_test.cpp): the per-wavelength ratios at null collisions.
TEST(VolPathGrid, ChromaticRgbGridTransmittanceMatchesTheHomogeneousMediumPerBucket) {
  std::string rgb = "[";
  for (int i = 0; i < 27; ++i) rgb += " 0.2 0.9 2";
  const std::string grid =
      "MakeNamedMedium \"ink\" \"string type\" \"rgbgrid\" \"integer nx\" 3 \"integer ny\" 3 "
      "\"integer nz\" 3 \"point3 p0\" [-2 -2 -2] \"point3 p1\" [2 2 2] \"rgb sigma_a\" " +
      rgb + " ] \"rgb sigma_s\" " + rgb + " ] \"float scale\" 0.5\n";
  // The same absorption, no scattering: sigma_s 0 in the homogeneous medium would differ, so
  // both scatter; a narrow view sees the unscattered light plus scattered sky, the same in both.
  const std::string homogeneous =
      "MakeNamedMedium \"ink\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.2 0.9 2] "
      "\"rgb sigma_s\" [0.2 0.9 2] \"float scale\" 0.5\n";
  // The 3^3 grid is constant within |x| < 2 - 2/3 (the outer half cells fade): a ball of 1.2.
  const Stats a = render(narrow_view(kSpectralFilm, 64) + "WorldBegin\n" + grid + kSky + ball("ink", "", 1.2f));
  const Stats b = render(narrow_view(kSpectralFilm, 64) + "WorldBegin\n" + homogeneous + kSky + ball("ink", "", 1.2f));
  const Stats open = render(narrow_view(kSpectralFilm, 4) + "WorldBegin\n" + kSky);
  for (int c = 3; c < 6; ++c) {
    EXPECT_NEAR(a.mean[c], b.mean[c], 5 * std::hypot(a.se[c], b.se[c])) << "bucket " << c - 3;
    EXPECT_LT(b.mean[c], 0.9 * open.mean[c]);  // the medium is seen
  }
  EXPECT_LT(b.mean[3], 0.8 * b.mean[5]);  // and chromatic: blue (400-500 nm, B = 2) darker than red
}

// A point light 1 unit above a diffuse disk seen from 2 units away, all inside a grid fog
// (constant over the scene's extent): the clear scene's radiance times exp(-sigma 3).
TEST(VolPathGrid, PointLightInAbsorbingGridFogIsAttenuatedAlongBothSegments) {
  const std::string fog = grid_medium(
      "fog", 4, [](float, float, float) { return 1.f; },
      "\"spectrum sigma_a\" [400 0.1 499.99 0.1 500.01 0.3 599.99 0.3 600.01 0.6 700 0.6] \"rgb sigma_s\" [0 0 0] "
      "\"float scale\" 1");
  const double sigma[3] = {0.1, 0.3, 0.6};
  auto scene = [&](bool foggy, int spp) {
    // The fog fills a sphere of radius 1.45 around (0, 0, 0.5), inside the grid's constant part.
    return fog + fmt::format(R"(LookAt 1.41421356 0 1.41421356  0 0 0  0 1 0
Camera "perspective" "float fov" 0.2
{}
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 5
WorldBegin
LightSource "point" "point3 from" [0 0 1] "rgb I" [1 1 1]
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "disk" "float radius" 1
{})",
                             kSpectralFilm, spp, foggy ? ball("fog", "", 1.49f) : "");
  };
  // The camera (at distance 2) sits outside the ball of radius 1.49: its ray crosses fog for
  // 1.49 units, the shadow ray from the disk's centre to the light for 1.
  const Stats clear = render(scene(false, 4));
  const Stats foggy = render(scene(true, 64));
  for (int b = 0; b < 3; ++b) {
    const int c = 3 + b;
    ASSERT_GT(clear.mean[c], 0.0);
    const double expected = clear.mean[c] * std::exp(-sigma[b] * (1.0 + 1.49));
    EXPECT_NEAR(foggy.mean[c], expected, 5 * foggy.se[c] + 1e-6) << "bucket " << b;
  }
}

std::string furnace_view(int spp) {
  return fmt::format(R"(LookAt 0 0 4  0 0 0  0 1 0
Camera "perspective" "float fov" 30
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 1000
)",
                     spp);
}

// Lossless, chromatic, anisotropic, strongly varying density (0 to 3 between neighbours).
std::string lossy_grid(double sigma_a) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  return grid_medium(
      "cloud", 6, [&](float, float, float) { return u(rng) < 0.25f ? 0.f : 3.f * u(rng); },
      fmt::format("\"rgb sigma_a\" [{0} {0} {0}] \"rgb sigma_s\" [0.5 1 2] \"float g\" 0.6", sigma_a));
}

TEST(VolPathGrid, WhiteFurnaceHeterogeneousGridVanishesUnderAUniformSky) {
  const Stats open = render(furnace_view(1) + "WorldBegin\n" + kSky);
  const Stats cloudy = render(furnace_view(64) + "WorldBegin\n" + lossy_grid(0) + kSky + ball("cloud", "", 1.9f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloudy.mean[c], open.mean[c], 5 * cloudy.se[c] + 1e-6) << "channel " << c;
  // ... and with absorption it is darker (the test can see the medium at all).
  const Stats dark = render(furnace_view(64) + "WorldBegin\n" + lossy_grid(0.3) + kSky + ball("cloud", "", 1.9f));
  for (int c = 0; c < 3; ++c) EXPECT_LT(dark.mean[c], open.mean[c] - 5 * dark.se[c]) << "channel " << c;
}

// Inside a black sphere emitting 1 inwards, light reaches the grid by light sampling (ratio
// tracked) and by phase-sampled rays that hit the wall (delta tracked), weighted by MIS.
TEST(VolPathGrid, WhiteFurnaceInsideAnEmittingEnclosureWithMisThroughTheGrid) {
  const std::string enclosure = R"(AttributeBegin
 ReverseOrientation
 AreaLightSource "diffuse" "rgb L" [1 1 1]
 Material "diffuse" "rgb reflectance" [0 0 0]
 Shape "sphere" "float radius" 6
AttributeEnd
)";
  const Stats open = render(furnace_view(1) + "WorldBegin\n" + enclosure);
  const Stats cloudy = render(furnace_view(64) + "WorldBegin\n" + lossy_grid(0) + enclosure + ball("cloud", "", 1.9f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloudy.mean[c], open.mean[c], 5 * cloudy.se[c] + 1e-6) << "channel " << c;
}

TEST(VolPathGrid, WhiteFurnaceCloudMediumVanishesUnderAUniformSky) {
  const std::string cloud =
      "AttributeBegin\nTranslate -1 -1 -1\nScale 2 2 2\nMakeNamedMedium \"cloud\" \"string type\" \"cloud\" "
      "\"float density\" 2 \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [2 4 6] \"float g\" 0.4\nAttributeEnd\n";
  const Stats open = render(furnace_view(1) + "WorldBegin\n" + kSky);
  const Stats cloudy = render(furnace_view(64) + "WorldBegin\n" + kSky + cloud + ball("cloud", "", 1.8f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloudy.mean[c], open.mean[c], 5 * cloudy.se[c] + 1e-6) << "channel " << c;
}

// A constant grid and the homogeneous medium of the same coefficients render the same image
// (means within their joint noise), with scattering, absorption, an area light and a floor.
TEST(VolPathGrid, ConstantGridRendersAsTheHomogeneousMedium) {
  const std::string coefficients = "\"rgb sigma_a\" [0.1 0.2 0.3] \"rgb sigma_s\" [1.2 0.9 0.6] \"float g\" 0.3";
  const std::string grid = grid_medium(
      "m", 4, [](float, float, float) { return 1.f; }, coefficients);
  const std::string homogeneous = "MakeNamedMedium \"m\" \"string type\" \"homogeneous\" " + coefficients + "\n";
  auto scene = [&](const std::string& medium) {
    return furnace_view(64) + "WorldBegin\n" + medium + R"(AttributeBegin
 AreaLightSource "diffuse" "rgb L" [4 4 4]
 Material "diffuse" "rgb reflectance" [0 0 0]
 Shape "bilinearmesh" "point3 P" [-0.5 1.6 -0.5  0.5 1.6 -0.5  -0.5 1.6 0.5  0.5 1.6 0.5]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "bilinearmesh" "point3 P" [-3 -1.4 -3  -3 -1.4 3  3 -1.4 -3  3 -1.4 3]
)" + ball("m", "", 1.4f);
  };
  const Stats a = render(scene(grid)), b = render(scene(homogeneous));
  for (int c = 0; c < 3; ++c) {
    ASSERT_GT(b.mean[c], 0.01);
    EXPECT_NEAR(a.mean[c], b.mean[c], 5 * std::hypot(a.se[c], b.se[c])) << "channel " << c;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
