// OpenEXR files without OpenImageIO (render/exr_file.h): channel order as OpenImageIO 2.4 gives
// it (the expected lists were read by OpenImageIO's Python binding from files with these
// channels), values and names through a write and a read, a data window that does not start at
// (0, 0) and half channels written by the OpenEXR library directly, a truncated file, and no
// libOpenImageIO in the process after EXR files went through image_io.
#include <gtest/gtest.h>
#include <link.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <regex>

#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "core/error.h"
#include "render/exr_file.h"
#include "render/gbuffer.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::vector<std::string> reordered(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());  // an EXR stores its channels sorted by name
  std::vector<std::string> out;
  for (int i : oiio_channel_order(names)) out.push_back(names[i]);
  return out;
}

TEST(ExrFile, ChannelOrderIsOpenImageIOs) {
  // Read by OpenImageIO 2.4 from eyetrace's gbuffer film (main's build, before this reader).
  EXPECT_EQ(reordered({"R",
                       "G",
                       "B",
                       "Albedo.R",
                       "Albedo.G",
                       "Albedo.B",
                       "P.X",
                       "P.Y",
                       "P.Z",
                       "dzdx",
                       "dzdy",
                       "N.X",
                       "N.Y",
                       "N.Z",
                       "Ns.X",
                       "Ns.Y",
                       "Ns.Z",
                       "u",
                       "v",
                       "Variance.R",
                       "Variance.G",
                       "Variance.B",
                       "RelativeVariance.R",
                       "RelativeVariance.G",
                       "RelativeVariance.B"}),
            (std::vector<std::string>{"R",
                                      "G",
                                      "B",
                                      "dzdx",
                                      "dzdy",
                                      "u",
                                      "v",
                                      "Albedo.R",
                                      "Albedo.G",
                                      "Albedo.B",
                                      "N.X",
                                      "N.Y",
                                      "N.Z",
                                      "Ns.X",
                                      "Ns.Y",
                                      "Ns.Z",
                                      "P.X",
                                      "P.Y",
                                      "P.Z",
                                      "RelativeVariance.R",
                                      "RelativeVariance.G",
                                      "RelativeVariance.B",
                                      "Variance.R",
                                      "Variance.G",
                                      "Variance.B"}));
  // And from files written by OpenImageIO with these names (its special names, any case).
  EXPECT_EQ(reordered({"A", "B", "G", "R", "Z", "a", "Y", "zeta", "Alpha", "diffuse.A", "diffuse.R", "diffuse.x",
                       "diffuse.Blue", "rgb.red"}),
            (std::vector<std::string>{"R", "G", "B", "Y", "A", "a", "Alpha", "Z", "zeta", "diffuse.R", "diffuse.Blue",
                                      "diffuse.A", "diffuse.x", "rgb.red"}));
  // A layer with X and Y or Z (a position, a normal) orders X, Y, Z after R, G, B, before A.
  EXPECT_EQ(reordered({"N.R", "N.Z", "N.x"}), (std::vector<std::string>{"N.R", "N.x", "N.Z"}));
  EXPECT_EQ(reordered({"A", "R", "Y", "Z", "b"}), (std::vector<std::string>{"R", "b", "Y", "A", "Z"}));
  EXPECT_EQ(reordered({"N.B", "N.G", "N.X"}), (std::vector<std::string>{"N.G", "N.B", "N.X"}));
  EXPECT_EQ(reordered({"L.Z", "L.q"}), (std::vector<std::string>{"L.Z", "L.q"}));
}

TEST(ExrFile, GbufferImageReadsBackByNameWithItsMetadata) {
  test::TempDir dir("eyetrace-exr");
  Image img;
  img.width = 5;
  img.height = 3;
  img.channel_names = {"R", "G", "B"};
  for (const std::string& n : GBuffer::channel_names()) img.channel_names.push_back(n);
  img.channels = int(img.channel_names.size());
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  // Distinct values, one of them beyond half's range, and a negative one.
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i) * 0.37f - 11.f;
  img.pixels[7] = 1e30f;
  const std::string path = dir.file("g.exr");
  write_image(path, img, {{"eyetrace:scene", "a b.pbrt"}, {"spectralLayoutVersion", "1.0"}});

  Image back = read_image(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  ASSERT_EQ(back.channels, img.channels);
  EXPECT_EQ(back.channel_names, reordered(img.channel_names));
  for (int c = 0; c < img.channels; ++c) {
    int bc = int(std::find(back.channel_names.begin(), back.channel_names.end(), img.channel_names[c]) -
                 back.channel_names.begin());
    ASSERT_LT(bc, back.channels) << img.channel_names[c];
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) EXPECT_EQ(back.at(x, y, bc), img.at(x, y, c)) << img.channel_names[c];
  }
  EXPECT_EQ(read_image_attribute(path, "eyetrace:scene"), "a b.pbrt");
  EXPECT_EQ(read_image_attribute(path, "spectralLayoutVersion"), "1.0");
  EXPECT_EQ(read_image_attribute(path, "absent"), "");
  EXPECT_TRUE(std::regex_match(read_image_attribute(path, "DateTime"),
                               std::regex("[0-9]{4}:[0-9]{2}:[0-9]{2} [0-9]{2}:[0-9]{2}:[0-9]{2}")));
  // Nothing is left beside the output (the temporary was renamed into place).
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(ExrFile, HalfChannelsOverAnOffsetDataWindow) {
  test::TempDir dir("eyetrace-exr");
  const std::string path = dir.file("w.exr");
  // A 4x2 data window at (2, 3) inside a 10x10 display window; Y and A, half floats.
  const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(9, 9)), data(Imath::V2i(2, 3), Imath::V2i(5, 4));
  Imf::Header h(display, data);
  h.channels().insert("Y", Imf::Channel(Imf::HALF));
  h.channels().insert("A", Imf::Channel(Imf::HALF));
  std::vector<half> px(4 * 2 * 2);
  for (size_t i = 0; i < px.size(); ++i) px[i] = half(0.25f * float(i));  // exact in half
  Imf::FrameBuffer fb;
  char* origin = reinterpret_cast<char*>(px.data()) - (2 + 3 * 4) * 2 * sizeof(half);
  fb.insert("Y", Imf::Slice(Imf::HALF, origin, 2 * sizeof(half), 4 * 2 * sizeof(half)));
  fb.insert("A", Imf::Slice(Imf::HALF, origin + sizeof(half), 2 * sizeof(half), 4 * 2 * sizeof(half)));
  {
    Imf::OutputFile out(path.c_str(), h);
    out.setFrameBuffer(fb);
    out.writePixels(2);
  }
  Image back = read_image(path);
  ASSERT_EQ(back.width, 4);
  ASSERT_EQ(back.height, 2);
  ASSERT_EQ(back.channel_names, (std::vector<std::string>{"Y", "A"}));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 2; ++c) EXPECT_EQ(back.at(x, y, c), 0.25f * float((y * 4 + x) * 2 + c));
}

TEST(ExrFile, TruncatedFileIsAnErrorNamingIt) {
  test::TempDir dir("eyetrace-exr");
  Image img;
  img.width = 64;
  img.height = 64;
  img.pixels.assign(64 * 64 * 3, 0.5f);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i % 97);
  const std::string path = dir.file("t.exr");
  write_image(path, img);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  try {
    read_image(path);
    FAIL() << "a truncated file was read";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

// IEC 61966-2-1 encoding, written out independently of image_io.
float srgb_encode(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f; }

// Whether an object whose path contains `name` is mapped into this process.
bool mapped(const char* name) {
  struct Query {
    const char* name;
    bool found;
  } q{name, false};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto* q = static_cast<Query*>(data);
        if (info->dlpi_name && std::strstr(info->dlpi_name, q->name)) q->found = true;
        return 0;
      },
      &q);
  return q.found;
}

TEST(ExrFile, ExrInputAndOutputMapNoOpenImageIO) {
  // In one process with tests that load the module (a whole-binary run) there is nothing to
  // tell; ctest runs each test alone, so there it always runs.
  if (mapped("libeyetrace_oiio")) GTEST_SKIP() << "an earlier test in this process loaded the module";
  // Linked into the test program (as into eyetrace) it would be here before anything is read.
  ASSERT_FALSE(mapped("libOpenImageIO"));
  test::TempDir dir("eyetrace-exr");
  Image img;
  img.width = img.height = 2;
  img.pixels = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  write_image(dir.file("a.exr"), img, {{"eyetrace:x", "1"}});
  EXPECT_EQ(read_image(dir.file("a.exr")).pixels, img.pixels);
  EXPECT_EQ(read_image_attribute(dir.file("a.exr"), "eyetrace:x"), "1");
  EXPECT_FALSE(mapped("libOpenImageIO"));
  EXPECT_TRUE(mapped("libOpenEXR"));  // the check sees libraries loaded by name
}

TEST(ExrFile, OtherFormatsLoadTheModule) {
  test::TempDir dir("eyetrace-exr");
  Image img;
  img.width = img.height = 2;
  img.pixels = {0, 0.5f, 1, 0.2f, 0.2f, 0.2f, 1, 1, 1, 0, 0, 0};
  write_image(dir.file("a.png"), img, {{"eyetrace:x", "png"}});
  EXPECT_TRUE(mapped("libeyetrace_oiio"));
  EXPECT_TRUE(mapped("libOpenImageIO"));
  Image back = read_image(dir.file("a.png"));
  ASSERT_EQ(back.pixels.size(), img.pixels.size());
  // 8-bit sRGB codes: the encoded value rounded, so within half a code.
  for (size_t i = 0; i < img.pixels.size(); ++i)
    EXPECT_NEAR(back.pixels[i], srgb_encode(img.pixels[i]), 0.5f / 255.f + 1e-6f) << i;
  EXPECT_EQ(read_image_attribute(dir.file("a.png"), "eyetrace:x"), "png");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
