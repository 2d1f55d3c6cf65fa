// The "imagemap" texture: images written here (EXR by image_io, an 8-bit PNG by
// support/png_writer.h) are read back at texel centres; 8-bit values are decoded with the sRGB
// formula written out below; wrap modes; missing and unreadable files are errors that name the
// parameter and the path.
#include <gtest/gtest.h>

#include <unistd.h>
#include "../support/params.h"
#include "../support/png_writer.h"
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/transform.h"
#include "render/image_io.h"
#include "scene/texture_store.h"
#include "textures/imagemap_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

Param str(const std::string& name, const std::string& v) {
  Param p;
  p.type = "string";
  p.name = name;
  p.loc = SourceLoc{"tex.pbrt", 5, 9};
  p.strings = {v};
  return p;
}

constexpr auto number = test::number_param;

// IEC 61966-2-1 decoding, written independently of the code under test.
double srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

class ImagemapTest : public ::testing::Test {
 protected:
  static constexpr int kW = 4, kH = 2;

  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("eyetrace_imagemap_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    // Float RGB: texel (x, y) = (x / 4, y / 2, 0.125 (x + 4 y)), row 0 at the top.
    Image f;
    f.width = kW;
    f.height = kH;
    f.pixels.resize(kW * kH * 3);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        f.at(x, y, 0) = x / 4.f, f.at(x, y, 1) = y / 2.f, f.at(x, y, 2) = 0.125f * (x + 4 * y);
      }
    write_image((dir_ / "rgb.exr").string(), f);
    // 8-bit grey with the byte values below.
    std::vector<unsigned char> g = {0, 10, 64, 128, 200, 255, 33, 90};
    test::write_grey_png((dir_ / "grey.png").string(), kW, kH, g);
    bytes_ = g;
    std::ofstream(dir_ / "notes.png") << "this is not an image\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // uv of the centre of texel (x, y), y counted from the top row.
  static TextureEvalContext texel(int x, int y) {
    TextureEvalContext c;
    c.uv = Vec2((x + 0.5f) / kW, 1.f - (y + 0.5f) / kH);
    return c;
  }

  fs::path dir_;
  std::vector<unsigned char> bytes_;
};

TEST_F(ImagemapTest, FloatImageTexelsReadBackExactly) {
  ParameterList p;
  p.add(str("filename", "rgb.exr"));
  TextureStore store;
  auto t = create_imagemap_image_texture(TextureContext{p, Transform(), store, dir_.string()});
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      RGB v = t->rgb(texel(x, y));
      EXPECT_NEAR(v.r, x / 4.f, 1e-6f) << x << "," << y;
      EXPECT_NEAR(v.g, y / 2.f, 1e-6f) << x << "," << y;
      EXPECT_NEAR(v.b, 0.125f * (x + 4 * y), 1e-6f) << x << "," << y;
    }
  // As a spectrum: the texel's RGB as a reflectance, or unbounded when the use asks for it.
  const SampledWavelengths lambda = test::wavelengths();
  TextureEvalContext c = texel(3, 1);
  EXPECT_TRUE(test::same(t->evaluate(c, lambda), test::albedo(t->rgb(c), lambda), 0.f));
  c.spectrum_type = SpectrumType::Unbounded;
  EXPECT_TRUE(
      test::same(t->evaluate(c, lambda), Spectrum::from_rgb(t->rgb(c), SpectrumType::Unbounded).sample(lambda), 0.f));
  // A float lookup of a colour image averages the channels (as pbrt-v4).
  auto f = create_imagemap_float_texture(TextureContext{p, Transform(), store, dir_.string()});
  EXPECT_NEAR(f->evaluate(texel(3, 1)), (0.75f + 0.5f + 0.875f) / 3.f, 1e-6f);
}

TEST_F(ImagemapTest, BilinearHalfwayBetweenTexels) {
  ParameterList p;
  p.add(str("filename", (dir_ / "rgb.exr").string()));  // absolute path
  p.add(str("wrap", "clamp"));
  TextureStore store;
  auto t = create_imagemap_image_texture(TextureContext{p, Transform(), store, ""});
  TextureEvalContext c;
  c.uv = Vec2(2.f / kW, 0.75f);  // between texels x = 1 and 2 of the top row
  EXPECT_NEAR(t->rgb(c).r, 0.375f, 1e-6f);
}

TEST_F(ImagemapTest, EightBitPngIsDecodedFromSrgb) {
  ParameterList p;
  p.add(str("filename", "grey.png"));
  TextureStore store;
  auto t = create_imagemap_float_texture(TextureContext{p, Transform(), store, dir_.string()});
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double expected = srgb_decode(bytes_[y * kW + x] / 255.0);
      EXPECT_NEAR(t->evaluate(texel(x, y)), expected, 1e-5) << int(bytes_[y * kW + x]);
    }
}

TEST_F(ImagemapTest, LinearEncodingScaleAndInvert) {
  TextureStore store;
  ParameterList lin;
  lin.add(str("filename", "grey.png"));
  lin.add(str("encoding", "linear"));
  lin.add(number("float", "scale", {2.0}));
  auto t = create_imagemap_image_texture(TextureContext{lin, Transform(), store, dir_.string()});
  EXPECT_NEAR(t->rgb(texel(3, 0)).g, 2.0 * 128 / 255.0, 1e-5);
  ParameterList inv;
  inv.add(str("filename", "grey.png"));
  inv.add(str("encoding", "gamma 2.2"));
  Param b;
  b.type = "bool";
  b.name = "invert";
  b.bools = {true};
  inv.add(b);
  auto u = create_imagemap_float_texture(TextureContext{inv, Transform(), store, dir_.string()});
  EXPECT_NEAR(u->evaluate(texel(3, 0)), 1.0 - std::pow(128 / 255.0, 2.2), 1e-5);
}

TEST_F(ImagemapTest, WrapModes) {
  TextureStore store;
  auto make = [&](const char* wrap) {
    ParameterList p;
    p.add(str("filename", "rgb.exr"));
    p.add(str("wrap", wrap));
    p.add(str("filter", "point"));
    return create_imagemap_image_texture(TextureContext{p, Transform(), store, dir_.string()});
  };
  TextureEvalContext outside = texel(1, 0);
  outside.uv.x += 1.f;  // one period to the right
  EXPECT_NEAR(make("repeat")->rgb(outside).r, 0.25f, 1e-6f);
  EXPECT_NEAR(make("clamp")->rgb(outside).r, 0.75f, 1e-6f);  // last column
  EXPECT_EQ(make("black")->rgb(outside), RGB(0.f));
}

TEST_F(ImagemapTest, WideFootprintSeesTheImageAverage) {
  // g is 0 on the top row and 0.5 on the bottom one. A point lookup at a top-row texel
  // centre gives 0; a footprint as wide as the image (MIP-filtered) gives the mean 0.25.
  ParameterList p;
  p.add(str("filename", "rgb.exr"));
  p.add(str("filter", "trilinear"));
  TextureStore store;
  auto t = create_imagemap_image_texture(TextureContext{p, Transform(), store, dir_.string()});
  TextureEvalContext c = texel(1, 0);
  EXPECT_NEAR(t->rgb(c).g, 0.f, 1e-6f);
  c.footprint = 4.f;
  EXPECT_NEAR(t->rgb(c).g, 0.25f, 1e-3f);
}

TEST_F(ImagemapTest, MissingFileNamesParameterAndPath) {
  ParameterList p;
  p.add(str("filename", "nope.exr"));
  TextureStore store;
  try {
    create_imagemap_image_texture(TextureContext{p, Transform(), store, dir_.string()});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("tex.pbrt:5:9"), std::string::npos) << m;
    EXPECT_NE(m.find("\"filename\""), std::string::npos) << m;
    EXPECT_NE(m.find((dir_ / "nope.exr").string()), std::string::npos) << m;
  }
}

TEST_F(ImagemapTest, UnreadableFileIsAnError) {
  ParameterList p;
  p.add(str("filename", "notes.png"));
  TextureStore store;
  try {
    create_imagemap_float_texture(TextureContext{p, Transform(), store, dir_.string()});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("cannot read image"), std::string::npos) << m;
    EXPECT_NE(m.find("notes.png"), std::string::npos) << m;
  }
}

TEST_F(ImagemapTest, UnknownFilterAndWrapAreErrors) {
  TextureStore store;
  ParameterList p;
  p.add(str("filename", "rgb.exr"));
  p.add(str("filter", "lanczos"));
  EXPECT_THROW(create_imagemap_float_texture(TextureContext{p, Transform(), store, dir_.string()}), SceneError);
  ParameterList q;
  q.add(str("filename", "rgb.exr"));
  q.add(str("wrap", "octahedralsphere"));
  EXPECT_THROW(create_imagemap_float_texture(TextureContext{q, Transform(), store, dir_.string()}), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
