#include "render/png_file.h"

#include <png.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

#include "render/image_library.h"

namespace eyetrace {

namespace {

// libpng reports errors by longjmp. The two functions that can jump hold nothing with a
// destructor, so a jump skips none (C++ allows longjmp only then); their callers own the memory.
struct PngError {
  char message[256] = "";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* e = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(e->message, sizeof e->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // e.g. unknown chunks: the pixels are still right

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int channels = 0, bit_depth = 0;
  bool srgb_chunk = false;
  double file_gamma = 0.;  // the gAMA chunk's value (0: none)
};

// Reads the header and sets the expansions: palette to RGB, transparency to alpha, grey of
// 1, 2 or 4 bits to 8, interlaced passes merged.
bool read_png_header(png_structp png, png_infop info, std::FILE* file, PngHeader* h) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_read_info(png, info);
  const int color_type = png_get_color_type(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  png_set_interlace_handling(png);
  h->srgb_chunk = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
  if (png_get_valid(png, info, PNG_INFO_gAMA)) png_get_gAMA(png, info, &h->file_gamma);
  png_read_update_info(png, info);
  h->width = png_get_image_width(png, info);
  h->height = png_get_image_height(png, info);
  h->channels = png_get_channels(png, info);
  h->bit_depth = png_get_bit_depth(png, info);
  return true;
}

bool read_png_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

struct PngReader {
  PngError error;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::FILE* file = nullptr;
  ~PngReader() {
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
  }
  [[noreturn]] void fail() const { throw std::runtime_error(error.message[0] ? error.message : "not a readable PNG"); }
};

std::vector<std::string> png_channel_names(int channels) {
  switch (channels) {
    case 1: return {"Y"};
    case 2: return {"Y", "A"};
    case 3: return {"R", "G", "B"};
    default: return {"R", "G", "B", "A"};
  }
}

}  // namespace

bool is_png_file(const std::string& path) {
  unsigned char sig[8] = {};
  std::ifstream in(path, std::ios::binary);
  return in.read(reinterpret_cast<char*>(sig), 8) && png_sig_cmp(sig, 0, 8) == 0;
}

PngSamples read_png_samples(const std::string& path, ImageFileFormat* format) {
  PngReader r;
  r.file = std::fopen(path.c_str(), "rb");
  if (!r.file) throw std::runtime_error(std::strerror(errno));
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.error, on_png_error, on_png_warning);
  if (!r.png) throw std::runtime_error("libpng cannot start");
  r.info = png_create_info_struct(r.png);
  if (!r.info) throw std::runtime_error("libpng cannot start");
  PngHeader h;
  if (!read_png_header(r.png, r.info, r.file, &h)) r.fail();
  const size_t row_bytes = size_t(h.width) * size_t(h.channels) * size_t(h.bit_depth / 8);
  if (h.width == 0 || h.height == 0 || h.channels < 1 || h.channels > 4 || (h.bit_depth != 8 && h.bit_depth != 16))
    throw std::runtime_error("unsupported PNG layout");
  // libpng allows sides of a million pixels, so a header of a few bytes could ask for terabytes.
  // Deflate compresses at most 1032:1 and the expansions above at most multiply the stored
  // bytes by 8 (1-bit grey to 8 bits), so a larger image cannot be in the file: refuse it
  // before allocating.
  const double file_bytes = double(std::filesystem::file_size(path));
  if (double(row_bytes) * double(h.height) > 8.0 * 1032.0 * file_bytes + double(1 << 20))
    throw std::runtime_error(
        fmt::format("{} x {} pixels cannot be in a file of {} bytes", h.width, h.height, std::uintmax_t(file_bytes)));

  PngSamples out;
  out.width = int(h.width);
  out.height = int(h.height);
  out.channels = h.channels;
  out.bit_depth = h.bit_depth;
  out.data.resize(row_bytes * h.height);
  std::vector<png_bytep> rows(h.height);
  for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = out.data.data() + size_t(y) * row_bytes;
  if (!read_png_rows(r.png, rows.data())) r.fail();

  *format = ImageFileFormat{};
  format->integer = true;
  format->eight_bit = h.bit_depth == 8;
  format->alpha_channel = h.channels == 2 ? 1 : h.channels == 4 ? 3 : -1;
  // gAMA stores the encoding exponent (1/2.2 for the usual files): 1.0 means linear values.
  format->color_space = !h.srgb_chunk && h.file_gamma > 0. && std::abs(h.file_gamma - 1.) < 0.01 ? "linear" : "sRGB";
  return out;
}

Image read_png(const std::string& path, ImageFileFormat* format) { return to_image(read_png_samples(path, format)); }

Image to_image(const PngSamples& s) {
  Image image;
  image.width = s.width;
  image.height = s.height;
  image.channels = s.channels;
  image.channel_names = png_channel_names(s.channels);
  image.pixels.resize(size_t(s.width) * s.height * s.channels);
  if (s.bit_depth == 8) {
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(s.data[i]) / 255.f;
  } else {  // 16 bits, big-endian in the file
    for (size_t i = 0; i < image.pixels.size(); ++i)
      image.pixels[i] = float((unsigned(s.data[2 * i]) << 8) | s.data[2 * i + 1]) / 65535.f;
  }
  return image;
}

}  // namespace eyetrace
