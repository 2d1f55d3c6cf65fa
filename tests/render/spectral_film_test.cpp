// The spectral film (Film "spectral"): its buckets, its estimator and its output.
//  - bucket geometry and pbrt-v4's channel names;
//  - the estimator fed directly: stratified wavelengths give a constant spectrum's value in
//    every bucket exactly, also when only the hero wavelength survives; a sample that is not
//    finite at any wavelength that counts leaves the film untouched;
//  - end to end through the renderer: emitters of known constant and non-constant spectral
//    radiance seen by a pinhole, and a diffuse surface of tabulated reflectance under a known
//    uniform sky, each bucket against the analytic mean of the radiance over the bucket, within
//    4 standard errors of the image mean (pixels are independent: the "independent" sampler);
//  - the R, G, B channels of a spectral film are the rgb film's, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "../support/unity_id.h"
#include "core/error.h"
#include "render/film.h"
#include "render/image_io.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

#include "../support/render_text.h"
#include "../support/unit_box_filter.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(SpectralFilm, BucketsAndPbrtChannelNames) {
  const SpectralBuckets b{16, 400.f, 700.f};
  EXPECT_DOUBLE_EQ(b.width(), 18.75);
  EXPECT_DOUBLE_EQ(b.centre(0), 409.375);
  EXPECT_EQ(b.channel_name(0), "S0.409,375nm");
  EXPECT_EQ(b.channel_name(15), "S0.690,625nm");
  EXPECT_EQ(b.bucket_of(400.f), 0);
  EXPECT_EQ(b.bucket_of(418.74f), 0);
  EXPECT_EQ(b.bucket_of(418.76f), 1);
  EXPECT_EQ(b.bucket_of(700.f), 15);  // the long end belongs to the last bucket
  EXPECT_EQ(b.bucket_of(399.99f), -1);
  EXPECT_EQ(b.bucket_of(700.01f), -1);
  EXPECT_EQ(b.bucket_of(std::nanf("")), -1);
  const SpectralBuckets pbrt{3, 360.f, 830.f};  // pbrt-v4's default range
  EXPECT_EQ(pbrt.channel_name(0), "S0.438,333nm");
  EXPECT_EQ(pbrt.channel_name(2), "S0.751,667nm");
}

Film spectral_film(int buckets = 16, IVec2 size = IVec2(2, 1)) {
  return Film(size, PixelBounds{IVec2(0), size}, std::make_unique<UnitBox>(), 1.f,
              SpectralBuckets{buckets, 400.f, 700.f});
}

// Wavelengths uniform over the buckets' range at K evenly spaced u: each of the four
// stratified wavelengths visits every bucket equally often, so the estimator's mean is exact.
TEST(SpectralFilm, ConstantSpectrumGivesItsValueInEveryBucket) {
  Film film = spectral_film();
  const int K = 1600;
  for (int k = 0; k < K; ++k) {
    SampledWavelengths l = SampledWavelengths::sample_uniform((k + 0.5f) / K, 400.f, 700.f);
    EXPECT_TRUE(film.add_sample(IVec2(0, 0), SampledSpectrum(2.5f), l, 0.75f));
  }
  for (int b = 0; b < 16; ++b) EXPECT_NEAR(film.bucket_value(IVec2(0, 0), b), 2.5f, 2.5e-6f) << "bucket " << b;
  EXPECT_EQ(film.bucket_value(IVec2(1, 0), 3), 0.f);  // no sample yet
  Image img = film.image();
  ASSERT_EQ(img.channels, 19);
  ASSERT_EQ(img.channel_names.size(), 19u);
  EXPECT_EQ(img.channel_names[2], "B");
  EXPECT_EQ(img.channel_names[3], "S0.409,375nm");
  EXPECT_EQ(img.at(0, 0, 3 + 7), film.bucket_value(IVec2(0, 0), 7));
  EXPECT_EQ(film.image_metadata().at("spectralLayoutVersion"), "1.0");
  EXPECT_EQ(film.image_metadata().at("emissiveUnits"), "W.m^-2.sr^-1");
  EXPECT_EQ(film.image_metadata().at("eyetrace:spectral_buckets"), "16 400 700");
}

// After terminate_secondary() the hero has density pdf / 4 and stands for all four; the
// others contribute nothing, whatever their values (NaN included).
TEST(SpectralFilm, TerminatedWavelengthsAddNothingAndTheHeroStandsForAll) {
  Film film = spectral_film();
  const int K = 1600;
  SampledSpectrum L(0.5f);
  for (int i = 1; i < kSpectrumSamples; ++i) L[i] = std::nanf("");
  for (int k = 0; k < K; ++k) {
    SampledWavelengths l = SampledWavelengths::sample_uniform((k + 0.5f) / K, 400.f, 700.f);
    l.terminate_secondary();
    EXPECT_TRUE(film.add_sample(IVec2(1, 0), L, l, 1.f));
  }
  for (int b = 0; b < 16; ++b) EXPECT_NEAR(film.bucket_value(IVec2(1, 0), b), 0.5f, 1e-6f) << "bucket " << b;
  EXPECT_EQ(film.nonfinite_samples(), 0u);
}

// The renderer's own density (pbrt-v4's visible sampling over 360-830 nm): wavelengths outside
// the buckets count for RGB only, and the buckets still average to the constant.
TEST(SpectralFilm, VisibleWavelengthSamplingIsUnbiased) {
  Film film = spectral_film(8);
  const int K = 1 << 16;
  for (int k = 0; k < K; ++k) {
    SampledWavelengths l = SampledWavelengths::sample_visible((k + 0.5f) / K);
    film.add_sample(IVec2(0, 0), SampledSpectrum(1.f), l, 1.f);
  }
  // Evenly spaced u: the error is the quadrature error of 2^18 points, far below 1e-3.
  for (int b = 0; b < 8; ++b) EXPECT_NEAR(film.bucket_value(IVec2(0, 0), b), 1.f, 1e-3f) << "bucket " << b;
}

TEST(SpectralFilm, SampleNotFiniteAtAnyCountingWavelengthLeavesTheFilmUntouched) {
  Film film = spectral_film();
  SampledWavelengths l = SampledWavelengths::sample_uniform(0.1f, 400.f, 700.f);
  ASSERT_TRUE(film.add_sample(IVec2(0, 0), SampledSpectrum(1.f), l, 1.f));
  const std::vector<double> before = film.accumulators();
  for (int i = 0; i < kSpectrumSamples; ++i) {
    for (float bad : {std::nanf(""), INFINITY, -INFINITY}) {
      SampledSpectrum L(1.f);
      L[i] = bad;
      EXPECT_FALSE(film.add_sample(IVec2(0, 0), L, l, 1.f)) << "wavelength " << i << " value " << bad;
    }
  }
  // A live wavelength outside the buckets (380 nm) still counts for RGB: its NaN is refused.
  SampledWavelengths wide = SampledWavelengths::sample_uniform(0.01f, 380.f, 720.f);
  ASSERT_LT(wide[0], 400.f);
  SampledSpectrum L(1.f);
  L[0] = std::nanf("");
  EXPECT_FALSE(film.add_sample(IVec2(0, 0), L, wide, 1.f));
  // A non-finite filter weight, and radiance whose estimate overflows float.
  EXPECT_FALSE(film.add_sample(IVec2(0, 0), SampledSpectrum(1.f), l, std::nanf("")));
  EXPECT_FALSE(film.add_sample(IVec2(0, 0), SampledSpectrum(3e38f), l, 1.f));
  EXPECT_EQ(film.nonfinite_samples(), 4u * 3u + 3u);
  const std::vector<double> after = film.accumulators();
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ(std::memcmp(after.data(), before.data(), after.size() * sizeof(double)), 0);
  for (float v : film.image().pixels) EXPECT_TRUE(std::isfinite(v));
}

TEST(SpectralFilm, AccumulatorsHoldTheBucketsAndRestoreExactly) {
  Film whole = spectral_film(5), first = spectral_film(5);
  // r, g, b, weight, 3 splat sums, the squared luminances, 3 share sums, 5 buckets, their splats
  // and their share sums
  EXPECT_EQ(whole.accumulators_per_pixel(), 26u);
  auto add = [](Film& f, int k) {
    SampledWavelengths l = SampledWavelengths::sample_visible(0.137f * k - std::floor(0.137f * k));
    SampledSpectrum L(0.3f + 0.1f * k);
    L[2] = 1.f / (k + 1);
    f.add_sample(IVec2(k % 2, 0), L, l, 0.25f + 0.1f * k);
  };
  for (int k = 0; k < 20; ++k) add(whole, k);
  for (int k = 0; k < 10; ++k) add(first, k);
  Film resumed = spectral_film(5);
  resumed.restore(first.accumulators(), 3);
  for (int k = 10; k < 20; ++k) add(resumed, k);
  const std::vector<double> a = resumed.accumulators(), b = whole.accumulators();
  ASSERT_EQ(a.size(), 2u * 26u);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  EXPECT_EQ(resumed.nonfinite_samples(), 3u);
  Film rgb(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>());
  EXPECT_THROW(rgb.restore(a, 0), std::invalid_argument);  // an RGB film's 8 per pixel
  EXPECT_THROW(resumed.restore(rgb.accumulators(), 0), std::invalid_argument);
}

TEST(SpectralFilm, ImageIsWrittenAsNamedFloatExrChannelsAndNeverAsPng) {
  auto dir = std::filesystem::temp_directory_path() / "eyetrace_spectral_film_test";
  std::filesystem::create_directories(dir);
  Film film = spectral_film(4);
  film.add_sample(IVec2(1, 0), SampledSpectrum(0.8f), SampledWavelengths::sample_uniform(0.2f, 400.f, 700.f), 1.f);
  const Image img = film.image();
  const std::string exr = (dir / "s.exr").string();
  write_image(exr, img, film.image_metadata());
  const Image back = read_image(exr);
  EXPECT_EQ(back.channel_names,
            (std::vector<std::string>{"R", "G", "B", "S0.437,500nm", "S0.512,500nm", "S0.587,500nm", "S0.662,500nm"}));
  ASSERT_EQ(back.pixels.size(), img.pixels.size());
  for (size_t i = 0; i < img.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], img.pixels[i]);  // float32
  EXPECT_EQ(read_image_attribute(exr, "spectralLayoutVersion"), "1.0");
  EXPECT_EQ(read_image_attribute(exr, "eyetrace:spectral_buckets"), "4 400 700");
  try {
    write_image((dir / "s.png").string(), img);
    ADD_FAILURE() << "a 7-channel PNG was written";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("7-channel image (a spectral film's) can only be written as .exr"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "s.png"));
}

// --- End to end ---------------------------------------------------------------------------

struct BucketMeans {
  std::vector<double> mean, std_error;  // over the image's pixels, per bucket
  SpectralBuckets buckets;
};

BucketMeans render_buckets(const std::string& text) {
  set_warnings_enabled(false);
  RenderSetup s = build_render_setup(parse_scene_string(text, "spectral.pbrt", "/"), {});
  RenderCounters counters;
  RenderOptions opts;
  opts.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  BucketMeans m;
  m.buckets = s.film->buckets();
  const Image img = s.film->image();
  for (int b = 0; b < m.buckets.count; ++b) {
    const test::MeanAndError e = test::channel_mean_and_error(img, 3 + b);
    m.mean.push_back(e.mean);
    m.std_error.push_back(e.std_error);
  }
  return m;
}

// (1 / width) * integral of f over bucket b: the trapezoid rule at 0.01 nm (the test spectra are
// piecewise linear, so this is exact to ~1e-7).
template <typename F>
double bucket_mean(const SpectralBuckets& buckets, int b, F&& f) {
  const double lo = buckets.lambda_min + b * buckets.width();
  const int n = int(std::lround(buckets.width() / 0.01));
  const double h = buckets.width() / n;
  double s = 0.5 * (f(lo) + f(lo + buckets.width()));
  for (int i = 1; i < n; ++i) s += f(lo + i * h);
  return s * h / buckets.width();
}

template <typename F>
void expect_buckets(const BucketMeans& m, F&& radiance, const std::string& what) {
  ASSERT_GT(m.buckets.count, 0) << what;
  for (int b = 0; b < m.buckets.count; ++b) {
    const double expected = bucket_mean(m.buckets, b, radiance);
    if (expected == 0.0) {  // e.g. RGB white (D65 of the CIE table) beyond 780 nm
      EXPECT_EQ(m.mean[b], 0.0) << what << ", bucket " << b;
      continue;
    }
    // The test must be able to fail: the noise is a small fraction of the value.
    EXPECT_LT(m.std_error[b], 0.015 * expected) << what << ", bucket " << b;
    EXPECT_NEAR(m.mean[b], expected, 4.0 * m.std_error[b] + 2e-4 * expected)
        << what << ", bucket " << b << " (" << m.buckets.centre(b) << " nm), standard error " << m.std_error[b];
  }
}

// A pinhole looking at a diffuse emitter that fills the view (radiance is the same everywhere).
std::string emitter_scene(const std::string& light, const std::string& film_params = "") {
  return fmt::format(R"(LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 10
Film "spectral" "integer xresolution" 32 "integer yresolution" 32 {}
Sampler "independent" "integer pixelsamples" 128
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
AreaLightSource "diffuse" {}
Shape "sphere" "float radius" 1
)",
                     film_params, light);
}

const std::vector<float> kLambda = {400.f, 450.f, 520.f, 600.f, 700.f};
const std::vector<float> kValues = {0.2f, 1.5f, 0.4f, 2.f, 0.8f};

std::string pairs(const std::vector<float>& lambda, const std::vector<float>& values) {
  std::string s;
  for (size_t i = 0; i < lambda.size(); ++i) s += fmt::format(" {} {}", lambda[i], values[i]);
  return s;
}

TEST(SpectralFilm, ConstantEmitterSeenDirectly) {
  // A spectrum given for a light is normalised to luminance 1 (core/spectrum.h): a flat one
  // becomes 1 everywhere, times "scale".
  BucketMeans m = render_buckets(emitter_scene(R"("spectrum L" [400 7 700 7] "float scale" 2.5)"));
  const Spectrum flat = Spectrum::tabulated({400.f, 700.f}, {7.f, 7.f}, SpectrumType::Illuminant);
  EXPECT_NEAR(flat(550.f), 1.f, 1e-6f);
  expect_buckets(
      m, [&](double l) { return 2.5 * flat(float(l)); }, "flat emitter");
}

// The physical-units recipe of docs/spectral.md: "float scale" = the tabulated spectrum's
// luminance in eyetrace's normalisation (Y relative to the equal-energy spectrum 1) undoes the
// normalisation, so the light emits the table's values, in the table's units.
TEST(SpectralFilm, TabulatedEmitterInPhysicalUnitsSeenDirectly) {
  const float y = Spectrum::tabulated(kLambda, kValues, SpectrumType::Unbounded).luminance();
  BucketMeans m = render_buckets(
      emitter_scene(fmt::format(R"("spectrum L" [{}] "float scale" {:.9g})", pairs(kLambda, kValues), y)));
  expect_buckets(
      m, [&](double l) { return interpolate_spectrum(kLambda, kValues, float(l)); }, "tabulated emitter");
}

// pbrt-v4's range and another bucket count; the emitter is the colour space's white (D65 of
// luminance 1) given as RGB: a non-constant spectrum the renderer itself defines.
TEST(SpectralFilm, RgbWhiteEmitterOverPbrtRange) {
  BucketMeans m = render_buckets(
      emitter_scene(R"("rgb L" [1 1 1])", R"("integer nbuckets" 10 "float lambdamin" 360 "float lambdamax" 830)"));
  EXPECT_EQ(m.buckets.count, 10);
  const Spectrum white = Spectrum::from_rgb(RGB(1.f), SpectrumType::Illuminant);
  expect_buckets(
      m, [&](double l) { return white(float(l)); }, "D65 emitter");
}

// A diffuse disk of tabulated reflectance filling the view under a uniform sky of radiance 1:
// every direction of its upper hemisphere sees the sky, so it reflects exactly R(lambda).
TEST(SpectralFilm, DiffuseSurfaceOfTabulatedReflectanceUnderUniformSky) {
  const std::vector<float> lambda = {400.f, 480.f, 560.f, 640.f, 700.f};
  const std::vector<float> rho = {0.9f, 0.1f, 0.6f, 0.05f, 0.7f};
  BucketMeans m = render_buckets(fmt::format(R"(LookAt 0 3 0  0 0 0  0 0 1
Camera "perspective" "float fov" 10
Film "spectral" "integer xresolution" 32 "integer yresolution" 32 "integer nbuckets" 12
Sampler "independent" "integer pixelsamples" 128
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
LightSource "infinite" "spectrum L" [400 1 700 1]
Material "diffuse" "spectrum reflectance" [{}]
Rotate -90 1 0 0
Shape "disk" "float radius" 100
)",
                                             pairs(lambda, rho)));
  const Spectrum sky = Spectrum::tabulated({400.f, 700.f}, {1.f, 1.f}, SpectrumType::Illuminant);
  expect_buckets(
      m, [&](double l) { return interpolate_spectrum(lambda, rho, float(l)) * sky(float(l)); }, "diffuse disk");
}

// The spectral film changes nothing of R, G, B: same wavelengths, same sums.
TEST(SpectralFilm, RgbChannelsAreTheRgbFilmsBitForBit) {
  auto scene = [](const std::string& film) {
    return fmt::format(R"(LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "{}" "integer xresolution" 24 "integer yresolution" 16
Sampler "zsobol" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 4
PixelFilter "gaussian"
WorldBegin
LightSource "point" "point3 from" [2 3 -3] "blackbody I" 3000 "float scale" 20
Material "diffuse" "rgb reflectance" [0.6 0.5 0.1]
Shape "sphere" "float radius" 1
Translate 0 -1 0
Rotate 90 1 0 0
Material "conductor"
Shape "disk" "float radius" 5
)",
                       film);
  };
  set_warnings_enabled(false);
  auto render = [](const std::string& text) {
    RenderSetup s = build_render_setup(parse_scene_string(text, "rgb.pbrt", "/"), {});
    RenderCounters counters;
    RenderOptions opts;
    opts.progress = false;
    opts.threads = 2;
    s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
    return s;
  };
  RenderSetup rgb = render(scene("rgb")), spectral = render(scene("spectral"));
  const std::vector<double> a = rgb.film->accumulators(), b = spectral.film->accumulators();
  // The spectral film adds 16 buckets, their splats and their shares.
  const size_t na = Film::kAccumulatorsPerPixel, nb = na + Film::kBucketAccumulators * 16;
  ASSERT_EQ(b.size(), a.size() / na * nb);
  for (size_t p = 0; p < a.size() / na; ++p)
    EXPECT_EQ(std::memcmp(&a[na * p], &b[nb * p], na * sizeof(double)), 0) << "pixel " << p;
  const Image ia = rgb.film->image(), ib = spectral.film->image();
  for (int y = 0; y < ia.height; ++y)
    for (int x = 0; x < ia.width; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(ia.at(x, y, c), ib.at(x, y, c));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
