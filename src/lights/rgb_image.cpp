#include "lights/rgb_image.h"

#include <algorithm>
#include <cctype>

#include "core/srgb.h"
#include "render/image_io.h"
#include "render/image_library.h"

namespace eyetrace {
namespace {

bool says_linear(std::string cs) {
  std::transform(cs.begin(), cs.end(), cs.begin(), [](unsigned char c) { return std::tolower(c); });
  return cs.find("linear") != std::string::npos || cs == "scene_linear";
}

// Index of the channel named `name`, else `fallback` (if it exists), else channel 0.
int channel_index(const Image& img, const char* name, int fallback) {
  for (int c = 0; c < int(img.channel_names.size()); ++c)
    if (img.channel_names[c] == name) return c;
  return fallback < img.channels ? fallback : 0;
}

}  // namespace

RGB RGBImage::nearest(Vec2 st) const {
  int x = std::clamp(int(st.x * float(width)), 0, width - 1);
  int y = std::clamp(int(st.y * float(height)), 0, height - 1);
  return at(x, y);
}

RGB RGBImage::bilerp(Vec2 st) const {
  float x = st.x * float(width) - 0.5f, y = st.y * float(height) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float dx = x - float(x0), dy = y - float(y0);
  auto px = [&](int xi, int yi) { return at(std::clamp(xi, 0, width - 1), std::clamp(yi, 0, height - 1)); };
  return (1.f - dx) * (1.f - dy) * px(x0, y0) + dx * (1.f - dy) * px(x0 + 1, y0) + (1.f - dx) * dy * px(x0, y0 + 1) +
         dx * dy * px(x0 + 1, y0 + 1);
}

std::optional<RGBImage> read_rgb_image(const std::string& path, std::string* error, size_t* non_finite) {
  Image data;
  ImageFileFormat format;
  if (!read_image(path, &data, &format, error)) return std::nullopt;
  if (data.width <= 0 || data.height <= 0 || data.channels <= 0) {
    *error = "the image is empty";
    return std::nullopt;
  }
  const int nc = data.channels;
  bool decode = format.integer && !says_linear(format.color_space);
  int ch[3] = {channel_index(data, "R", 0), channel_index(data, "G", 1), channel_index(data, "B", 2)};
  if (nc < 3) ch[0] = ch[1] = ch[2] = 0;

  RGBImage img;
  img.width = data.width;
  img.height = data.height;
  img.pixels.resize(size_t(img.width) * img.height);
  size_t bad = 0;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      float v = data.pixels[i * nc + ch[c]];
      if (!std::isfinite(v)) ++bad, v = 0.f;
      v = std::max(v, 0.f);
      img.pixels[i][c] = decode ? srgb_to_linear(v) : v;
    }
  }
  if (non_finite) *non_finite = bad;
  return img;
}

}  // namespace eyetrace
