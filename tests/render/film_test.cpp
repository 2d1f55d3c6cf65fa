// Film accumulation, crop windows and image output.
#include "render/film.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"

#include "../support/unit_box_filter.h"

namespace eyetrace {
namespace {

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

}  // namespace
}  // namespace eyetrace
