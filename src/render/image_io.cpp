#include "render/image_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/error.h"
#include "core/srgb.h"
#include "render/exr_file.h"
#include "render/image_library.h"
#include "render/image_library_loader.h"
#include "render/png_file.h"

namespace eyetrace {

namespace fs = std::filesystem;

static std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void write_image(const std::string& path, const Image& image, const std::map<std::string, std::string>& metadata) {
  std::string ext = lower_extension(path);
  bool is_float = ext == ".exr" || ext == ".hdr" || ext == ".pfm";
  if (!is_float && ext != ".png" && ext != ".jpg" && ext != ".jpeg" && ext != ".tif" && ext != ".tiff")
    throw_error(fmt::format("output \"{}\": unsupported image extension \"{}\" (use .exr or .png)", path, ext));
  if (!is_float && image.channels != 3)
    throw_error(fmt::format("output \"{}\": a {}-channel image (a spectral film's) can only be written as .exr", path,
                            image.channels));
  if (!image.channel_names.empty() && int(image.channel_names.size()) != image.channels)
    throw_error(fmt::format("output \"{}\": {} channel names for {} channels", path, image.channel_names.size(),
                            image.channels));
  if (image.pixels.size() != size_t(image.width) * image.height * image.channels || image.width <= 0 ||
      image.height <= 0)
    throw_error(fmt::format("output \"{}\": {} values for a {}x{} image of {} channels", path, image.pixels.size(),
                            image.width, image.height, image.channels));
  // Before anything is written: an image other than EXR needs the OpenImageIO module.
  ImageLibrary* library = ext == ".exr" ? nullptr : &image_library(path);
  fs::path target(path);
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);
  // The temporary keeps the real extension so OpenImageIO picks the right writer.
  std::random_device rd;
  fs::path tmp = dir / fmt::format(".{}.tmp{:08x}{}", target.stem().string(), rd(), ext);

  std::string err;
  bool ok = true;
  if (!library) {
    try {
      write_exr(tmp.string(), image, metadata);
    } catch (const std::exception& e) {
      ok = false;
      err = e.what();
    }
  } else {
    // 8-bit output converts a copy; float output writes the pixels as they are (a 4096x4096
    // film's are 200 MB: no copy).
    std::vector<float> encoded;
    if (!is_float) {
      encoded.resize(image.pixels.size());
      for (size_t i = 0; i < encoded.size(); ++i)
        encoded[i] = std::clamp(linear_to_srgb(std::isfinite(image.pixels[i]) ? image.pixels[i] : 0.f), 0.f, 1.f);
    }
    ok =
        library->write(tmp.string(), image, is_float ? image.pixels.data() : encoded.data(), !is_float, metadata, &err);
  }
  if (!ok) {
    fs::remove(tmp, ec);
    throw_error(fmt::format("output \"{}\": write failed: {}", path, err));
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw_error(fmt::format("output \"{}\": cannot move the finished image into place", path));
  }
}

void prepare_image_output(const std::string& path) {
  if (lower_extension(path) != ".exr") image_library(path);
}

bool read_image(const std::string& path, Image* image, ImageFileFormat* format, std::string* reason) {
  *format = ImageFileFormat{};
  try {
    if (is_exr_file(path)) {
      *image = read_exr(path);  // float pixels, linear
      return true;
    }
    if (is_png_file(path)) {
      *image = read_png(path, format);
      return true;
    }
    // A file that cannot be opened at all needs no image library to say so.
    if (!std::ifstream(path, std::ios::binary)) {
      *reason = std::strerror(errno);
      return false;
    }
    return image_library(path).read(path, image, format, reason);
  } catch (const SceneError& e) {  // the module cannot be loaded
    *reason = e.first().message;
  } catch (const std::exception& e) {
    *reason = e.what();
  }
  return false;
}

Image read_image(const std::string& path, ImageFileFormat* format) {
  Image img;
  std::string reason;
  if (!read_image(path, &img, format, &reason)) throw_error(fmt::format("image \"{}\": cannot read: {}", path, reason));
  return img;
}

Image read_image(const std::string& path) {
  ImageFileFormat format;
  return read_image(path, &format);
}

std::string read_image_attribute(const std::string& path, const std::string& name) {
  if (is_exr_file(path)) return read_exr_attribute(path, name);
  if (!std::ifstream(path, std::ios::binary)) return "";
  return image_library(path).attribute(path, name);
}

}  // namespace eyetrace
