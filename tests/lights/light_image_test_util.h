// Image files for the tests of lights that read one (goniometric, projection): a scratch folder
// removed when the test program exits, and float RGB images written from a function of the pixel.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/math.h"
#include "render/image_io.h"

namespace eyetrace {
namespace {

struct LightImageScratch {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("eyetrace_light_images_" + std::to_string(getpid()));
  LightImageScratch() { std::filesystem::create_directories(dir); }
  ~LightImageScratch() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

inline std::string scratch_path(const std::string& name) {
  static LightImageScratch scratch;
  return (scratch.dir / name).string();
}

// A float RGB image (EXR keeps NaN and infinities as written).
inline void write_rgb(const std::string& path, int w, int h, const std::function<RGB(int, int)>& pixel) {
  Image img;
  img.width = w;
  img.height = h;
  img.pixels.resize(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = pixel(x, y)[c];
  write_image(path, img);
}

}  // namespace
}  // namespace eyetrace
