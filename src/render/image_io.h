// Reading and writing images: OpenEXR through the OpenEXR library (render/exr_file.h), PNG
// input through libpng (render/png_file.h), every other format through OpenImageIO, loaded on
// demand (render/image_library.h). Writes go to a temporary file in the target's folder and are
// renamed into place, so an existing output is never half-written.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace eyetrace {

struct Image {
  int width = 0, height = 0, channels = 3;
  std::vector<float> pixels;  // linear, row-major, top row first
  // One name per channel (EXR), or empty: R, G, B. A spectral film's image is R, G, B and its
  // buckets (render/film.h).
  std::vector<std::string> channel_names;
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// .exr: linear float32 channels (named as `channel_names`) with `metadata` as string
// attributes; .png/.jpg/.tif: sRGB 8-bit after clamping, 3-channel images only (anything else
// is an error: a spectral image is EXR only). Throws SceneError naming the file on failure.
void write_image(const std::string& path, const Image& image, const std::map<std::string, std::string>& metadata = {});
// All channels as float, in the file's channel order (OpenImageIO's for EXR), with their names.
Image read_image(const std::string& path);
struct ImageFileFormat;  // render/image_library.h
// The same, and how the file stores its pixels (*format).
Image read_image(const std::string& path, ImageFileFormat* format);
// The same without throwing: false with the reason (which does not name the file) in *reason.
bool read_image(const std::string& path, Image* image, ImageFileFormat* format, std::string* reason);
// Makes sure `path` can be written later: for a format other than EXR, loads the OpenImageIO
// module now (an error naming the file if it cannot be), so a long render does not end in it.
void prepare_image_output(const std::string& path);
// Reads one string attribute from an image header ("" if absent).
std::string read_image_attribute(const std::string& path, const std::string& name);

}  // namespace eyetrace
