// PNG files written from the specification (ISO/IEC 15948), independent of libpng and of
// eyetrace's reader: the signature, IHDR, an optional PLTE, one zlib IDAT of rows each led by
// filter type 0, IEND (and a gAMA chunk on request); every chunk with its CRC-32.
#pragma once
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace eyetrace::test {

// PNG's colour types.
enum PngColour : uint8_t { kPngGrey = 0, kPngRgb = 2, kPngPalette = 3, kPngGreyAlpha = 4, kPngRgba = 6 };

// `rows` holds the packed bytes of each row without its filter byte (16-bit samples big-endian,
// samples below 8 bits packed from the high bit), `bit_depth` bits per sample; `palette` RGB
// triples for kPngPalette; `gamma_100000`, when not 0, a gAMA chunk (the encoding exponent
// times 100000).
inline void write_png(const std::string& path, int w, int h, PngColour colour, int bit_depth,
                      const std::vector<std::string>& rows, const std::string& palette = "",
                      uint32_t gamma_100000 = 0) {
  auto be32 = [](std::string& s, uint32_t v) {
    for (int i = 3; i >= 0; --i) s.push_back(char((v >> (8 * i)) & 0xff));
  };
  std::string file = "\x89PNG\r\n\x1a\n";
  auto chunk = [&](const char* type, const std::string& data) {
    be32(file, uint32_t(data.size()));
    std::string body = std::string(type) + data;
    file += body;
    be32(file, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
  };
  std::string ihdr;
  be32(ihdr, uint32_t(w));
  be32(ihdr, uint32_t(h));
  ihdr += char(bit_depth);
  ihdr += char(colour);
  ihdr += std::string(3, '\0');  // deflate, filter method 0, no interlace
  std::string raw;
  for (const std::string& row : rows) raw += '\0' + row;
  uLongf n = compressBound(uLong(raw.size()));
  std::string z(n, '\0');
  ASSERT_EQ(
      compress(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size())),
      Z_OK);
  z.resize(n);
  chunk("IHDR", ihdr);
  if (gamma_100000) {
    std::string g;
    be32(g, gamma_100000);
    chunk("gAMA", g);
  }
  if (colour == kPngPalette) chunk("PLTE", palette);
  chunk("IDAT", z);
  chunk("IEND", "");
  std::ofstream(path, std::ios::binary) << file;
}

// An 8-bit greyscale image from one byte per texel, rows top first.
inline void write_grey_png(const std::string& path, int w, int h, const std::vector<unsigned char>& bytes) {
  std::vector<std::string> rows;
  for (int y = 0; y < h; ++y) rows.emplace_back(reinterpret_cast<const char*>(&bytes[size_t(y) * w]), size_t(w));
  write_png(path, w, h, kPngGrey, 8, rows);
}

}  // namespace eyetrace::test
