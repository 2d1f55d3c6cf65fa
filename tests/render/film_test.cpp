// Film accumulation, crop windows and image output.
#include "render/film.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <utility>

#include "core/error.h"

#include "../support/unit_box_filter.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// pbrt-v4 rounds crop windows up: [ceil(x0 * w), ceil(x1 * w)).
TEST(Film, CropWindowMatchesPbrtRounding) {
  PixelBounds b = crop_to_pixels(IVec2(100, 50), Vec4(0.25f, 0.755f, 0.f, 0.5f));
  EXPECT_EQ(b.lo, IVec2(25, 0));
  EXPECT_EQ(b.hi, IVec2(76, 25));
}

TEST(Film, WeightedMeanAndNonFiniteSamplesDiscarded) {
  Film film(IVec2(4, 4), PixelBounds{IVec2(0), IVec2(4)}, std::make_unique<UnitBox>(), 2.f);
  film.add_sample(IVec2(1, 2), RGB(1.f, 2.f, 3.f), 1.f);
  film.add_sample(IVec2(1, 2), RGB(3.f, 2.f, 1.f), 3.f);
  EXPECT_FALSE(film.add_sample(IVec2(1, 2), RGB(std::nanf(""), 0.f, 0.f), 1.f));
  EXPECT_FALSE(film.add_sample(IVec2(1, 2), RGB(1.f / 0.f, 0.f, 0.f), 1.f));
  RGB v = film.pixel_value(IVec2(1, 2));
  // scale 2 x weighted mean (1*1 + 3*3)/4 = 2.5 in red.
  EXPECT_FLOAT_EQ(v.r, 5.f);
  EXPECT_FLOAT_EQ(v.g, 4.f);
  EXPECT_FLOAT_EQ(v.b, 3.f);
  EXPECT_EQ(film.nonfinite_samples(), 2u);
  EXPECT_EQ(film.pixel_value(IVec2(0, 0)), RGB(0.f));
}

// Normalised splats (box filter, dispersive eye): a pixel with share sums is (sum + splat) over
// them per XYZ channel, times equal-energy white. Where the radiance is the same at every
// wavelength (a grey region) each wavelength's term is that radiance times its share, so the
// pixel is exactly the radiance's colour whichever wavelengths landed, with whatever shares,
// here or by splat; the plain mean of the same terms is not (wavelength noise).
TEST(Film, NormalisedSplatsGiveAGreyRegionItsColourWhicheverWavelengthsLanded) {
  Film shared(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>(), 2.f);
  const float grey = 0.7f;
  for (int s = 0; s < 6; ++s) {
    const SampledWavelengths l = SampledWavelengths::sample_visible(0.61f * s - std::floor(0.61f * s) + 0.03f);
    SampledSpectrum share;
    for (int k = 0; k < kSpectrumSamples; ++k) share[k] = 0.2f + 0.45f * float((s + k) % 4);
    // A sample of pixel s % 2; its wavelength 3 landed in the other pixel when s % 3 == 0.
    const IVec2 own_pixel(s % 2, 0), other(1 - s % 2, 0);
    SampledSpectrum own = share, moved(0.f);
    if (s % 3 == 0) std::swap(own[3], moved[3]);
    ASSERT_TRUE(shared.add_sample(own_pixel, own * grey, l, 1.f));
    ASSERT_TRUE(shared.add_share(own_pixel, own, l));
    if (s % 3 == 0) {
      ASSERT_TRUE(shared.add_splat(other, moved * grey, l));
      ASSERT_TRUE(shared.add_share(other, moved, l));
    }
  }
  const RGB want = xyz_to_linear_srgb(equal_energy_xyz()) * (2.f * grey);  // the film's scale 2
  for (int x = 0; x < 2; ++x) {
    const RGB got = shared.pixel_value(IVec2(x, 0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-6f) << x << " " << c;
  }
  // The plain mean (no shares) of pixel 0's terms is off by the wavelengths' noise.
  Film plain(IVec2(1, 1), PixelBounds{IVec2(0), IVec2(1)}, std::make_unique<UnitBox>(), 2.f);
  for (int s = 0; s < 5; ++s) {
    const SampledWavelengths l = SampledWavelengths::sample_visible(0.61f * s - std::floor(0.61f * s) + 0.03f);
    plain.add_sample(IVec2(0, 0), SampledSpectrum(grey), l, 1.f);
  }
  const RGB off = plain.pixel_value(IVec2(0, 0)) - want;
  EXPECT_GT(std::max({std::abs(off.r), std::abs(off.g), std::abs(off.b)}), 0.01f);
  // A non-finite share is refused and counted; the pixel keeps its value.
  EXPECT_FALSE(shared.add_share(IVec2(0, 0), SampledSpectrum(std::numeric_limits<float>::infinity()),
                                SampledWavelengths::sample_visible(0.5f)));
  EXPECT_EQ(shared.nonfinite_samples(), 1u);
  EXPECT_NEAR(shared.pixel_value(IVec2(0, 0)).g, want.g, 2e-6f);
}

// A dispersive eye's sample whose radiance went into splats adds only its filter weight
// (Film::add_weight): the same pixel sums, bit for bit, as adding it with zero radiance, negative
// filter weights included; a non-finite weight is refused and counted by both.
TEST(Film, AddWeightIsASampleOfZeroRadiance) {
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.6f);
  Film a(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>(), 1.f);
  Film b(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>(), 1.f);
  SampledSpectrum L(0.f);
  L[1] = 0.7f;
  for (Film* f : {&a, &b}) f->add_splat(IVec2(1, 0), L, lambda);
  for (float w : {0.8f, -0.15f, 1.3f, std::nanf("")}) {
    EXPECT_EQ(a.add_weight(IVec2(1, 0), lambda, w), std::isfinite(w));
    EXPECT_EQ(b.add_sample(IVec2(1, 0), SampledSpectrum(0.f), lambda, w), std::isfinite(w));
  }
  const RGB va = a.pixel_value(IVec2(1, 0)), vb = b.pixel_value(IVec2(1, 0));
  EXPECT_NE(va.g, 0.f);
  EXPECT_EQ(std::memcmp(&va, &vb, sizeof(RGB)), 0);
  const std::vector<double> sa = a.accumulators(), sb = b.accumulators();  // every sum, signs of zeros too
  ASSERT_EQ(sa.size(), sb.size());
  EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size() * sizeof(double)), 0);
  EXPECT_EQ(a.nonfinite_samples(), 1u);
  EXPECT_EQ(b.nonfinite_samples(), 1u);
}

// A sample's four wavelengths splatted over their own blocks at once
// (Film::add_wavelength_splats) add what add_splats of each wavelength alone adds: to float
// rounding of the colour with the default response, bit for bit with a spectral film (which takes
// the general path); a non-finite wavelength is counted and dropped, the others kept.
TEST(Film, AddWavelengthSplatsIsEachWavelengthAlone) {
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.41f);
  WavelengthSplat s[kSpectrumSamples];
  for (int k = 0; k < kSpectrumSamples; ++k) {
    s[k].first = IVec2(k % 2, k / 3);
    s[k].nx = 2 + k % 2;
    s[k].ny = 2;
    for (int i = 0; i < WavelengthSplat::kMaxSpan; ++i) {
      s[k].wx[i] = 0.3f + 0.1f * float(i + k);
      s[k].wy[i] = 0.9f - 0.2f * float(i);
    }
  }
  s[2].nx = 0;  // counts nowhere
  SampledSpectrum L;
  for (int k = 0; k < kSpectrumSamples; ++k) L[k] = 0.5f + float(k);
  for (bool spectral : {false, true}) {
    for (bool nan : {false, true}) {
      SampledSpectrum l = L;
      if (nan) l[1] = std::nanf("");
      const SpectralBuckets buckets{spectral ? 8 : 0};
      const PixelBounds bounds{IVec2(0), IVec2(4, 3)};
      Film a(IVec2(4, 3), bounds, std::make_unique<UnitBox>(), 1.f, buckets);
      Film b(IVec2(4, 3), bounds, std::make_unique<UnitBox>(), 1.f, buckets);
      a.add_wavelength_splats(s, l, lambda);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        if (s[k].nx == 0) continue;
        SampledSpectrum one(0.f);
        one[k] = l[k];
        b.add_splats(s[k], one, lambda);
      }
      EXPECT_EQ(a.nonfinite_samples(), nan ? 1u : 0u);
      EXPECT_EQ(b.nonfinite_samples(), a.nonfinite_samples());
      const std::vector<double> sa = a.accumulators(), sb = b.accumulators();
      ASSERT_EQ(sa.size(), sb.size());
      // Each pixel's splat sums, by hand: wavelength k's colour times wx[column] wy[row].
      std::vector<RGB> want(12, RGB(0.f));
      for (int k = 0; k < kSpectrumSamples; ++k) {
        if (s[k].nx == 0 || !std::isfinite(l[k])) continue;
        SampledSpectrum one(0.f);
        one[k] = l[k];
        const RGB c = sampled_to_rgb(one, lambda);
        for (int r = 0; r < s[k].ny; ++r)
          for (int x = 0; x < s[k].nx; ++x)
            want[size_t((s[k].first.y + r) * 4 + s[k].first.x + x)] += s[k].wx[x] * s[k].wy[r] * c;
      }
      for (int p = 0; p < 12; ++p) {
        const RGB w = want[size_t(p)];
        const double* acc = sa.data() + size_t(p) * a.accumulators_per_pixel();  // splat r, g, b at 4..6
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(acc[4 + c], w[c], 1e-5 * std::abs(w[c]) + 1e-9) << p << " " << c;
      }
      if (spectral) {
        EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size() * sizeof(double)), 0) << nan;
        continue;
      }
      int nonzero = 0;
      for (size_t i = 0; i < sa.size(); ++i) {
        EXPECT_NEAR(sa[i], sb[i], 1e-6 * std::abs(sb[i])) << i << " " << nan;
        nonzero += sb[i] != 0.0;
      }
      EXPECT_GT(nonzero, 20) << nan;  // 11 pixels reached, three colour sums each
    }
  }
}

// pbrt-v4's maxcomponentvalue (RGBFilm::AddSample): a sample's sensor RGB times the imaging
// ratio is scaled so that its largest component is the value. For the cie1931 sensor the sensor
// RGB is XYZ. The film, with scale = imaging ratio 2 and maximum 1.5: a bright sample's pixel is
// its unclamped colour times k, one k for all channels, with k * max(XYZ) * 2 = 1.5 exactly; a
// dim sample is untouched, bit for bit.
SampledSpectrum constant_spectrum(float v) {
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = v;
  return s;
}

TEST(Film, MaxComponentValueScalesTheLargestSensorComponentToTheValue) {
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  FilmResponse clamp;
  clamp.max_component = 1.5f;
  clamp.imaging_ratio = 2.f;
  Film film(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>(), 2.f, {}, clamp);
  Film plain(IVec2(2, 1), PixelBounds{IVec2(0), IVec2(2, 1)}, std::make_unique<UnitBox>(), 2.f);
  for (Film* f : {&film, &plain}) {
    EXPECT_TRUE(f->add_sample(IVec2(0, 0), constant_spectrum(10.f), lambda, 1.f));
    EXPECT_TRUE(f->add_sample(IVec2(1, 0), constant_spectrum(0.1f), lambda, 1.f));
  }
  const Vec3 xyz = sampled_to_xyz(constant_spectrum(10.f), lambda);
  ASSERT_GT(max_component(xyz) * 2.f, 1.5f);
  const RGB bright = film.pixel_value(IVec2(0, 0)), unclamped = plain.pixel_value(IVec2(0, 0));
  const double k = double(bright.g) / unclamped.g;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(bright[c] / unclamped[c], k, 1e-6 * k) << c;
  EXPECT_NEAR(k * max_component(xyz) * 2.0, 1.5, 1e-6);
  EXPECT_EQ(film.pixel_value(IVec2(1, 0)), plain.pixel_value(IVec2(1, 0)));
  // A splat is clamped the same way.
  film.add_splat(IVec2(1, 0), constant_spectrum(10.f), lambda);
  plain.add_splat(IVec2(1, 0), constant_spectrum(10.f), lambda);
  const RGB diff = film.pixel_value(IVec2(1, 0)) - plain.pixel_value(IVec2(1, 0));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(diff[c], (bright[c] - unclamped[c]), 1e-5 * unclamped[c]) << c;
}

// With a camera the clamp acts on the camera's responses (before its XYZ matrix), and a
// non-finite sample is still rejected, never clamped into a finite value.
TEST(Film, MaxComponentValueClampsTheCamerasResponsesAndRejectsNonFinite) {
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.6f);
  FilmResponse r;
  r.sensor = std::make_shared<PixelSensor>(*PixelSensor::camera("sony_ilce_9", 5000.0));
  r.max_component = 0.5f;
  Film film(IVec2(1, 1), PixelBounds{IVec2(0), IVec2(1)}, std::make_unique<UnitBox>(), 1.f, {}, r);
  SampledSpectrum L = constant_spectrum(4.f);
  L[1] = 9.f;
  ASSERT_TRUE(film.add_sample(IVec2(0, 0), L, lambda, 1.f));
  const Vec3 resp = r.sensor->responses(L, lambda);
  ASSERT_GT(max_component(resp), 0.5f);
  const RGB want = xyz_to_linear_srgb(r.sensor->xyz(resp * (0.5f / max_component(resp))));
  const RGB got = film.pixel_value(IVec2(0, 0));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f * std::abs(want[c]) + 1e-7f) << c;
  L[2] = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(film.add_sample(IVec2(0, 0), L, lambda, 1.f));
  L[2] = std::nanf("");
  EXPECT_FALSE(film.add_sample(IVec2(0, 0), L, lambda, 1.f));
  EXPECT_EQ(film.nonfinite_samples(), 2u);
  EXPECT_EQ(film.pixel_value(IVec2(0, 0)), got);
}

// pbrt-v4's SpectralFilm also clamps the radiance its buckets see: L scaled so that its largest
// value, in pbrt-v4's units (ours over the integral of y-bar), is the maximum. A constant L of
// 1000 with maximum 2 gives buckets 2 * integral(y-bar) / 1000 of the unclamped ones.
TEST(Film, MaxComponentValueClampsASpectralFilmsBuckets) {
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.45f);
  FilmResponse r;
  r.max_component = 2.f;
  const SpectralBuckets buckets{8, 400.f, 700.f};
  Film film(IVec2(1, 1), PixelBounds{IVec2(0), IVec2(1)}, std::make_unique<UnitBox>(), 1.f, buckets, r);
  Film plain(IVec2(1, 1), PixelBounds{IVec2(0), IVec2(1)}, std::make_unique<UnitBox>(), 1.f, buckets);
  for (Film* f : {&film, &plain}) ASSERT_TRUE(f->add_sample(IVec2(0, 0), constant_spectrum(1000.f), lambda, 1.f));
  const double ratio = 2.0 * cie_y_integral() / 1000.0;
  int nonzero = 0;
  for (int b = 0; b < buckets.count; ++b) {
    const float v = plain.bucket_value(IVec2(0, 0), b);
    if (v != 0.f) ++nonzero;
    EXPECT_NEAR(film.bucket_value(IVec2(0, 0), b), v * ratio, 1e-5 * v) << b;
  }
  EXPECT_GT(nonzero, 0);
}

TEST(ImageIO, ExrRoundTripsExactlyAndPngIsSrgb) {
  auto dir = std::filesystem::temp_directory_path() / "eyetrace_image_io_test";
  std::filesystem::create_directories(dir);
  Image img;
  img.width = 3;
  img.height = 2;
  img.pixels = {0.f, 0.1f,  0.2f, 0.5f, 1.f, 2.f, 1e-3f, 0.25f, 0.75f,
                3.f, 0.04f, 0.9f, 0.f,  0.f, 1.f, 0.18f, 0.18f, 0.18f};
  std::string exr = (dir / "a.exr").string();
  write_image(exr, img, {{"eyetrace:samples_per_pixel", "16"}});
  Image back = read_image(exr);
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (size_t i = 0; i < img.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], img.pixels[i]);
  EXPECT_EQ(read_image_attribute(exr, "eyetrace:samples_per_pixel"), "16");
  std::string png = (dir / "a.png").string();
  write_image(png, img);
  Image p = read_image(png);
  // 18% grey encodes to sRGB 0.4613 (IEC 61966-2-1), i.e. 118/255.
  EXPECT_NEAR(p.at(2, 1, 0), 118.f / 255.f, 0.5f / 255.f);
  EXPECT_NEAR(p.at(1, 0, 2), 1.f, 1e-6f);  // 2.0 clamps to white
  // No temporary files are left behind.
  int files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.path().filename().string()[0] == '.';
  EXPECT_EQ(files, 0);
}

TEST(ImageIO, BadExtensionIsAnErrorAndLeavesExistingFileAlone) {
  auto dir = std::filesystem::temp_directory_path() / "eyetrace_image_io_test2";
  std::filesystem::create_directories(dir);
  Image img;
  img.width = img.height = 1;
  img.pixels = {1.f, 1.f, 1.f};
  EXPECT_THROW(write_image((dir / "x.bmpx").string(), img), SceneError);
  std::string exr = (dir / "keep.exr").string();
  write_image(exr, img);
  Image bad;  // zero-sized image: the writer fails, the old file must survive
  EXPECT_THROW(write_image(exr, bad), SceneError);
  EXPECT_EQ(read_image(exr).pixels[0], 1.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
