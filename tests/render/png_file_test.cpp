// PNG files read through libpng (render/png_file.h): files written from the specification
// (support/png_writer.h) in each colour type and bit depth read back as written, the values
// OpenImageIO reads from them (the reader used before; it multiplies colour by alpha), and
// damaged files are errors.
#include <gtest/gtest.h>

#include "../support/png_writer.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"

#include <filesystem>

#include "render/image_io.h"
#include "render/image_library.h"
#include "render/image_library_loader.h"
#include "render/png_file.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string bytes(std::initializer_list<int> v) {
  std::string s;
  for (int b : v) s.push_back(char(b));
  return s;
}

struct Case {
  const char* name;
  test::PngColour colour;
  int depth;
  std::vector<std::string> rows;  // 2 x 2 texels
  std::vector<std::string> channel_names;
  std::vector<float> values;  // what the reader must return, row-major
  std::string palette = "";
};

std::vector<Case> cases() {
  return {
      {"grey8", test::kPngGrey, 8, {bytes({0, 10}), bytes({128, 255})}, {"Y"}, {0.f, 10 / 255.f, 128 / 255.f, 1.f}},
      {"grey1", test::kPngGrey, 1, {bytes({0x80}), bytes({0x40})}, {"Y"}, {1.f, 0.f, 0.f, 1.f}},
      {"greyalpha8",
       test::kPngGreyAlpha,
       8,
       {bytes({1, 2, 3, 4}), bytes({5, 6, 7, 8})},
       {"Y", "A"},
       {1 / 255.f, 2 / 255.f, 3 / 255.f, 4 / 255.f, 5 / 255.f, 6 / 255.f, 7 / 255.f, 8 / 255.f}},
      {"rgb8",
       test::kPngRgb,
       8,
       {bytes({255, 0, 0, 0, 255, 0}), bytes({0, 0, 255, 51, 102, 153})},
       {"R", "G", "B"},
       {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2f, 0.4f, 0.6f}},
      {"rgba16",
       test::kPngRgba,
       16,
       {bytes({0xff, 0xff, 0, 0, 0x80, 0x00, 0x00, 0x01, 0, 0, 0, 0, 0, 0, 0xff, 0xff}),
        bytes({0x12, 0x34, 0x56, 0x78, 0x9a, 0xbc, 0xde, 0xf0, 0, 1, 0, 2, 0, 3, 0, 4})},
       {"R", "G", "B", "A"},
       {1.f, 0.f, 0x8000 / 65535.f, 1 / 65535.f, 0.f, 0.f, 0.f, 1.f, 0x1234 / 65535.f, 0x5678 / 65535.f,
        0x9abc / 65535.f, 0xdef0 / 65535.f, 1 / 65535.f, 2 / 65535.f, 3 / 65535.f, 4 / 65535.f}},
      {"palette8",
       test::kPngPalette,
       8,
       {bytes({0, 1}), bytes({1, 2})},
       {"R", "G", "B"},
       {1, 0, 0, 0, 0.2f, 1, 0, 0.2f, 1, 1, 1, 1},
       bytes({255, 0, 0, 0, 51, 255, 255, 255, 255})},
  };
}

// The case's 2 x 2 image as a file in `dir`; its path.
std::string write_case(const test::TempDir& dir, const Case& c) {
  const std::string path = dir.file(std::string(c.name) + ".png");
  test::write_png(path, 2, 2, c.colour, c.depth, c.rows, c.palette);
  return path;
}

TEST(PngFile, EveryColourTypeAndBitDepthReadsAsWritten) {
  test::TempDir dir("eyetrace-png");
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string path = write_case(dir, c);
    ASSERT_TRUE(is_png_file(path));
    ImageFileFormat format;
    Image im = read_png(path, &format);
    EXPECT_EQ(im.width, 2);
    EXPECT_EQ(im.height, 2);
    EXPECT_EQ(im.channel_names, c.channel_names);
    ASSERT_EQ(im.pixels.size(), c.values.size());
    for (size_t i = 0; i < c.values.size(); ++i) EXPECT_FLOAT_EQ(im.pixels[i], c.values[i]) << i;
    EXPECT_TRUE(format.integer);
    EXPECT_EQ(format.eight_bit, c.depth <= 8);
    EXPECT_EQ(format.alpha_channel, c.channel_names.back() == "A" ? int(c.channel_names.size()) - 1 : -1);
    EXPECT_EQ(format.color_space, "sRGB");
  }
}

TEST(PngFile, SameValuesAsOpenImageIO) {
  test::TempDir dir("eyetrace-png");
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string path = write_case(dir, c);
    ImageFileFormat ours_format, oiio_format;
    Image ours = read_png(path, &ours_format), oiio;
    std::string why;
    ASSERT_TRUE(image_library(path).read(path, &oiio, &oiio_format, &why)) << why;
    EXPECT_EQ(ours.channel_names, oiio.channel_names);
    ASSERT_EQ(ours.pixels.size(), oiio.pixels.size());
    // OpenImageIO associates colour with alpha (multiplies it in, rounded to the file's
    // integers); PNG, pbrt-v4 and this reader keep colour and alpha apart.
    const int n = ours.channels, alpha = ours_format.alpha_channel;
    const double quantum = c.depth == 16 ? 1 / 65535.0 : 1 / 255.0;
    for (size_t i = 0; i < ours.pixels.size(); ++i) {
      const int ch = int(i % size_t(n));
      const bool colour_with_alpha = alpha >= 0 && ch != alpha;
      const double a = colour_with_alpha ? ours.pixels[i - size_t(ch) + size_t(alpha)] : 1.0;
      EXPECT_NEAR(ours.pixels[i] * a, oiio.pixels[i], colour_with_alpha ? quantum : 1e-7) << i;
    }
    EXPECT_EQ(ours_format.alpha_channel, oiio_format.alpha_channel);
    EXPECT_EQ(ours_format.eight_bit, oiio_format.eight_bit);
  }
}

TEST(PngFile, GammaChunkOfOneSaysLinear) {
  test::TempDir dir("eyetrace-png");
  const std::string linear = dir.file("linear.png"), usual = dir.file("usual.png");
  test::write_png(linear, 1, 1, test::kPngGrey, 8, {bytes({7})}, "", 100000);
  test::write_png(usual, 1, 1, test::kPngGrey, 8, {bytes({7})}, "", 45455);
  ImageFileFormat format;
  EXPECT_FLOAT_EQ(read_png(linear, &format).pixels[0], 7 / 255.f);  // the values are not converted
  EXPECT_EQ(format.color_space, "linear");
  read_png(usual, &format);
  EXPECT_EQ(format.color_space, "sRGB");
}

TEST(PngFile, DamagedFilesAreErrorsNotCrashes) {
  test::TempDir dir("eyetrace-png");
  const std::string good = dir.file("good.png");
  test::write_png(good, 2, 2, test::kPngRgb, 8, {bytes({1, 2, 3, 4, 5, 6}), bytes({7, 8, 9, 10, 11, 12})});
  const std::string text = test::read_text(good);
  // Cut at every length past the signature: each is an error with a reason, never a crash.
  for (size_t n = 8; n < text.size(); n += 3) {
    const std::string cut = dir.file("cut.png");
    std::ofstream(cut, std::ios::binary) << text.substr(0, n);
    ImageFileFormat format;
    Image im;
    std::string why;
    EXPECT_FALSE(read_image(cut, &im, &format, &why)) << n;
    EXPECT_FALSE(why.empty()) << n;
  }
  // A flipped byte in the image data fails its CRC.
  std::string bad = text;
  bad[bad.size() - 20] ^= 0x5a;
  std::ofstream(dir.file("crc.png"), std::ios::binary) << bad;
  ImageFileFormat format;
  EXPECT_THROW(read_png(dir.file("crc.png"), &format), std::exception);
  // A header of 60000 x 60000 RGBA texels (14 GB) in a file of a hundred bytes is refused
  // before anything is allocated: deflate cannot hold it there.
  test::write_png(dir.file("huge.png"), 60000, 60000, test::kPngRgba, 8, {bytes({1, 2, 3, 4})});
  try {
    read_png(dir.file("huge.png"), &format);
    ADD_FAILURE() << "a 60000 x 60000 image was read from a tiny file";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("60000 x 60000 pixels cannot be in a file of"), std::string::npos) << e.what();
  }
  std::ofstream(dir.file("text.png")) << "not an image\n";
  EXPECT_FALSE(is_png_file(dir.file("text.png")));
  EXPECT_FALSE(is_png_file(dir.file("absent.png")));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
