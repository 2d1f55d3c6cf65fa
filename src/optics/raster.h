// A small RGB raster for the optics report's figures (spot diagram, chromatic curve): pixels,
// lines and a 5x7 bitmap font. The optics library does no image I/O; the caller writes the
// pixels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace eyetrace::optics {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel
  double um_per_pixel = 0.0;      // spot diagram: common scale of every panel
  double scale_bar_um = 0.0;      // spot diagram: length of the black bar drawn in each panel

  RgbImage() = default;
  RgbImage(int w, int h, Rgb fill = {255, 255, 255});
  // Pixels outside the image are ignored.
  void put(int x, int y, Rgb c);
  Rgb at(int x, int y) const;
  // A line of the given thickness (pixels, >= 1) from (x0, y0) to (x1, y1).
  void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1);
  // Text with its top-left corner at (x, y): 5x7 glyphs (digits, letters, space and
  // + - . , : ( ) / =; others blank) drawn at `scale` pixels per font pixel, 1 font pixel apart.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1);
  static int text_width(const std::string& s, int scale = 1) { return static_cast<int>(s.size()) * 6 * scale; }
  static int text_height(int scale = 1) { return 7 * scale; }
  // Copies `other` with its top-left corner at (x, y).
  void blit(const RgbImage& other, int x, int y);
};

}  // namespace eyetrace::optics
