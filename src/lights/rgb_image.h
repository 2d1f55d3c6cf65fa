// A linear-RGB image read once, when a light is created, for emission lookups (environment
// maps, textured area lights). Texture filtering is not wanted here: lights look pixels up
// exactly, so that sampling by pixel brightness matches what is returned.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"

namespace eyetrace {

struct RGBImage {
  int width = 0, height = 0;
  std::vector<RGB> pixels;  // row-major, top row first; finite and >= 0

  const RGB& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
  // The pixel containing st in [0,1]^2 (clamped to the edge).
  RGB nearest(Vec2 st) const;
  // Bilinear between pixel centres, clamped at the border (pbrt-v4's Image::Bilerp).
  RGB bilerp(Vec2 st) const;
};

// Reads `path` (render/image_io.h: EXR directly, other formats through OpenImageIO). Integer formats (PNG, JPEG,
// 8/16-bit TIFF) are taken as sRGB-encoded unless the file says it is linear; float formats (EXR, HDR, PFM) as linear.
// R, G, B channels by name (else the first three; one- or two-channel images are grey).
// Negative values become 0; non-finite ones become 0 and are counted in *non_finite.
// On failure returns nullopt with the reason in *error.
std::optional<RGBImage> read_rgb_image(const std::string& path, std::string* error, size_t* non_finite = nullptr);

}  // namespace eyetrace
