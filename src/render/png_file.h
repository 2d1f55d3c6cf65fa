// PNG files read through libpng itself, so that a scene's PNG textures and environment maps
// never load OpenImageIO (render/image_library.h says why that matters).
//
// What is read is what OpenImageIO 2.4 read before: every channel as float, integer values
// divided by 255 or 65535 and not decoded (the caller applies the encoding), palettes and
// transparency chunks expanded to RGB(A), grey below 8 bits widened; channels named Y, Y A,
// R G B or R G B A; the colour space "sRGB" unless a gAMA chunk of 1.0 says "linear".
#pragma once
#include <string>
#include <vector>

#include "render/image_io.h"

namespace eyetrace {

struct ImageFileFormat;  // render/image_library.h

// True when the file starts with PNG's eight-byte signature.
bool is_png_file(const std::string& path);

// The image and how the file stores it. Throws std::exception with libpng's reason (image_io.h
// names the file).
Image read_png(const std::string& path, ImageFileFormat* format);

// The same samples undecoded and unconverted, for readers that keep 8 bits (a quarter of the
// memory of floats): rows top first, channels interleaved, one byte per 8-bit sample, two
// (big-endian) per 16-bit sample.
struct PngSamples {
  int width = 0, height = 0, channels = 0, bit_depth = 8;
  std::vector<unsigned char> data;
};
PngSamples read_png_samples(const std::string& path, ImageFileFormat* format);
// As read_png gives them: floats, integers divided by their maximum, channels named.
Image to_image(const PngSamples& samples);

}  // namespace eyetrace
