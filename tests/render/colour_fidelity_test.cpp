// Colour fidelity of the spectral pipeline, end to end through the renderer (scene text in,
// linear sRGB pixels out): a white furnace returns its albedo exactly, the 24 patches of a
// colour checker given as sRGB come back within CIEDE2000 1 under the colour space's white
// light, a white card under a 6504 K blackbody has the blackbody's colour, and a white card
// under a 3000 K blackbody comes out neutral when the film is white balanced for 3000 K.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/ciede2000.h"
#include "../support/color_checker.h"
#include "../support/unity_id.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct ChannelMeans {
  double mean[3] = {0, 0, 0};
  double std_error[3] = {0, 0, 0};  // of the mean, from the spread of the pixels
};

// Renders `text` and averages each channel over the image.
ChannelMeans render_means(const std::string& text) {
  SceneDescription desc = parse_scene_string(text, "colour.pbrt", ".");
  RenderSetup s = build_render_setup(desc, {});
  RenderCounters counters;
  RenderOptions opts;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  Image img = s.film->image();
  ChannelMeans m;
  const size_t n = size_t(img.width) * img.height;
  for (int c = 0; c < 3; ++c) {
    double sum = 0, sum2 = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const double v = img.at(x, y, c);
        sum += v;
        sum2 += v * v;
      }
    m.mean[c] = sum / n;
    m.std_error[c] = std::sqrt(std::max(0.0, sum2 / n - m.mean[c] * m.mean[c]) / n);
  }
  return m;
}

// A diffuse sphere filling the view inside a uniform environment of radiance (1, 1, 1): the
// colour space's white, D65, of luminance 1. A convex object there reflects exactly its albedo.
std::string furnace(float rho) {
  return fmt::format(R"(
    LookAt 0 0 -3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 32 "integer yresolution" 32
    Sampler "halton" "integer pixelsamples" 256
    Integrator "path" "integer maxdepth" 50
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "rgb L" [1 1 1]
    Material "diffuse" "rgb reflectance" [{0} {0} {0}]
    Shape "sphere" "float radius" 1
  )",
                     rho);
}

// The issue's bar: albedo 1 and 0.8 come back within 0.3 % in every channel (pbrt-v3-spectral
// returns 0.911 for white). 262144 samples; the assertion also demands the estimate be that
// precise (its standard error below 0.1 %), so a noisy pass cannot hide a bias.
TEST(ColourFidelity, WhiteFurnaceReturnsTheAlbedo) {
  for (float rho : {1.f, 0.8f}) {
    ChannelMeans m = render_means(furnace(rho));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(m.mean[c], rho, 0.003 * rho) << "albedo " << rho << " channel " << c;
      EXPECT_LT(m.std_error[c], 0.001 * rho) << "albedo " << rho << " channel " << c;
    }
  }
}

double srgb_decode(int v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear sRGB to XYZ (IEC 61966-2-1), for the CIELAB comparison with D65 as the white.
std::array<double, 3> linear_srgb_to_xyz(double r, double g, double b) {
  return {0.4124564 * r + 0.3575761 * g + 0.1804375 * b, 0.2126729 * r + 0.7151522 * g + 0.0721750 * b,
          0.0193339 * r + 0.1191920 * g + 0.9503041 * b};
}

// Each patch as a diffuse sphere under the uniform white light: what comes back is the
// reflectance upsampled to a spectrum, lit by D65 and turned back into sRGB by the film.
TEST(ColourFidelity, ColourCheckerRoundTripsWithinDeltaE1) {
  const std::array<double, 3> white = linear_srgb_to_xyz(1, 1, 1);
  double worst = 0;
  for (const test::Patch& p : test::kColorChecker) {
    const double r = srgb_decode(p.r), g = srgb_decode(p.g), b = srgb_decode(p.b);
    std::string text = fmt::format(R"(
      LookAt 0 0 -3  0 0 0  0 1 0
      Camera "perspective" "float fov" 10
      Film "rgb" "integer xresolution" 8 "integer yresolution" 8
      Sampler "halton" "integer pixelsamples" 64
      Integrator "path" "integer maxdepth" 2
      PixelFilter "box"
      WorldBegin
      LightSource "infinite" "rgb L" [1 1 1]
      Material "diffuse" "rgb reflectance" [{} {} {}]
      Shape "sphere" "float radius" 1
    )",
                                   r, g, b);
    ChannelMeans m = render_means(text);
    const colour::Lab want = colour::xyz_to_lab(linear_srgb_to_xyz(r, g, b), white);
    const colour::Lab got = colour::xyz_to_lab(linear_srgb_to_xyz(m.mean[0], m.mean[1], m.mean[2]), white);
    const double de = colour::ciede2000(want, got);
    worst = std::max(worst, de);
    EXPECT_LT(de, 1.0) << p.name << ": rendered " << m.mean[0] << " " << m.mean[1] << " " << m.mean[2];
  }
  RecordProperty("worst_ciede2000", std::to_string(worst));
  std::printf("colour checker: worst CIEDE2000 %.3f\n", worst);
}

// The issue: "a blackbody light of 6504 K photographed through a pinhole onto a white diffuse
// card is neutral in the output's colour space within 1 %". It is not, physically: D65, the
// sRGB white, lies 0.0032 in CIE 1960 uv off the Planckian locus, and a 6504 K blackbody of
// luminance 1 is linear sRGB (1.04282, 0.98379, 1.03511), slightly magenta. Those numbers come
// from Planck's law, the CIE 1931 2-degree functions (CIE 15, 5 nm) and the IEC 61966-2-1
// matrix, with no eyetrace code: `/usr/bin/python3 tools/blackbody_reference.py --kelvin 6504`
// (the CIE's 1 nm table over 360-830 nm gives (1.04289, 0.98371, 1.03567), within 0.06 %).
// eyetrace does not white-balance, so the card must come back as that colour within 1 %.
// A uniform sky lights the flat card's whole front hemisphere: it reflects exactly the sky's
// radiance, of luminance 1. The test also demands a standard error below 0.2 %.
TEST(ColourFidelity, BlackbodyOnAWhiteCardIsTheBlackbodysColour) {
  const ChannelMeans m = render_means(R"(
    LookAt 0 0 3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 32 "integer yresolution" 32
    Sampler "halton" "integer pixelsamples" 256
    Integrator "path" "integer maxdepth" 2
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "blackbody L" [6504]
    Material "diffuse" "rgb reflectance" [1 1 1]
    Shape "disk" "float radius" 1
  )");
  const double want[3] = {1.04282, 0.98379, 1.03511};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(m.mean[c], want[c], 0.01 * want[c]) << "channel " << c;
    EXPECT_LT(m.std_error[c], 0.002 * want[c]) << "channel " << c;
  }
  std::printf("6504 K blackbody on a white card: (%.5f, %.5f, %.5f) +- (%.5f, %.5f, %.5f)\n", m.mean[0], m.mean[1],
              m.mean[2], m.std_error[0], m.std_error[1], m.std_error[2]);
}

// White balance end to end: the card above under a 3000 K blackbody sky, the film balanced for
// 3000 K (pbrt-v4 balances for a blackbody at 3000 * 1.4388 / 1.4380 = 3001.7 K below 4000 K,
// which differs from the light by 0.05 % in r/b). With the cie1931 sensor the Bradford matrix
// maps the balance white exactly, so the card must be neutral within 0.5 % (its noise is 0.05 %;
// measured 0.2 %); with a camera (Canon EOS 5D Mark IV) within the 5 % that pbrt-v4's
// least-squares fit allows (tests/render/pixel_sensor_test.cpp; measured (0.977, 1.004, 0.969)).
// Unbalanced the same card is (1.77, 0.84, 0.27): far from neutral.
std::string card_under_3000k(const std::string& film_params) {
  return R"(
    LookAt 0 0 3  0 0 0  0 1 0
    Camera "perspective" "float fov" 10
    Film "rgb" "integer xresolution" 16 "integer yresolution" 16 )" +
         film_params + R"(
    Sampler "halton" "integer pixelsamples" 256
    Integrator "path" "integer maxdepth" 2
    PixelFilter "box"
    WorldBegin
    LightSource "infinite" "blackbody L" [3000]
    Material "diffuse" "rgb reflectance" [1 1 1]
    Shape "disk" "float radius" 1
  )";
}

TEST(ColourFidelity, WhiteBalancedFilmMakesAWhiteCardUnderA3000KBlackbodyNeutral) {
  const struct {
    std::string film;
    double tolerance;
  } cases[] = {{R"("float whitebalance" 3000)", 0.005},
               {R"("string sensor" "canon_eos_5d_mkiv" "float whitebalance" 3000)", 0.05}};
  for (const auto& c : cases) {
    const ChannelMeans m = render_means(card_under_3000k(c.film));
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(m.mean[ch] / m.mean[1], 1.0, c.tolerance) << c.film << " channel " << ch;
      EXPECT_LT(m.std_error[ch], 0.003 * m.mean[ch]) << c.film << " channel " << ch;
    }
    std::printf("white card, 3000 K, %s: (%.5f, %.5f, %.5f) +- (%.5f, %.5f, %.5f)\n", c.film.c_str(), m.mean[0],
                m.mean[1], m.mean[2], m.std_error[0], m.std_error[1], m.std_error[2]);
  }
  const ChannelMeans raw = render_means(card_under_3000k(""));
  EXPECT_GT(raw.mean[0] / raw.mean[2], 2.0);
  std::printf("white card, 3000 K, no white balance: (%.5f, %.5f, %.5f)\n", raw.mean[0], raw.mean[1], raw.mean[2]);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
