// An image pyramid with pbrt-v4's texture filters (pbrt-v4's MIPMap, Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 4th ed., section 10.4.3): point, bilinear and trilinear lookups
// at the level the footprint picks, and elliptically weighted averaging (EWA).
//
// Built as pbrt-v4 builds it, so textured images match its: values decoded to linear before any
// filtering (the encoding per texel, as pbrt-v4's Image::GetChannel does), a side that is not a
// power of two resized up with a Lanczos windowed sinc (radius 2, tau 2) first, each level the
// 2x2 box average of the one below, down to 1x1. Levels of 8-bit images are stored as 8 bits
// (re-encoded), decoded through a 256-entry table: a quarter of the memory of floats.
// Immutable after construction, so any number of threads may look up at once.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "render/image_io.h"

namespace eyetrace {

// How stored texel values map to linear ones.
struct TexelEncoding {
  enum class Kind { Linear, SRGB, Gamma };
  Kind kind = Kind::Linear;
  float gamma = 1.f;  // Kind::Gamma: linear = stored^gamma
  float decode(float stored) const;
  float encode(float linear) const;
};

enum class MipFilter { Point, Bilinear, Trilinear, Ewa };
enum class MipWrap { Repeat, Black, Clamp };

class MipMap {
 public:
  // The first `channels` (1 or 3) channels of `image`, whose values are as the file stores them
  // (integers divided by their maximum), decoded by `encoding`. `eight_bit`: the file's values
  // are multiples of 1/255, and the levels keep them as bytes.
  MipMap(const Image& image, int channels, bool eight_bit, TexelEncoding encoding, MipWrap wrap);
  // An 8-bit image's samples, `stride` per texel, rows top first; the first `channels` of each
  // texel are kept (the rest, alpha, dropped in place).
  MipMap(std::vector<uint8_t> samples, int width, int height, int stride, int channels, TexelEncoding encoding,
         MipWrap wrap);

  int channels() const { return channels_; }
  int levels() const { return int(levels_.size()); }
  IVec2 resolution(int level) const { return {levels_[level].width, levels_[level].height}; }
  size_t bytes() const;

  // pbrt-v4's MIPMap::Filter: the filtered, linear value of each channel at (s, t) (t = 0 the
  // top row) with the footprint's derivatives dst0 = (ds/dx, dt/dx), dst1 = (ds/dy, dt/dy);
  // zero derivatives filter level 0 bilinearly (point: its nearest texel).
  void filter(MipFilter f, float max_anisotropy, Vec2 st, Vec2 dst0, Vec2 dst1, float* out) const;
  // One texel of a level, decoded; the wrap mode for coordinates outside (black: 0).
  float texel(int level, int x, int y, int c) const;
  void bilerp(int level, Vec2 st, float* out) const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<uint8_t> bytes;  // 8-bit images: encoded values
    std::vector<float> floats;   // the others: linear values
  };
  float stored(const Level& l, size_t i) const { return l.bytes.empty() ? l.floats[i] : decode_[l.bytes[i]]; }
  void ewa(int level, Vec2 st, Vec2 dst0, Vec2 dst1, float* out) const;
  void build_from_bytes(std::vector<uint8_t> bytes, int width, int height);
  // Level `levels_.size()` from its linear values (resized up first unless its sides are powers
  // of two), and every level above it.
  void build(std::vector<float> linear, int width, int height, bool eight_bit);
  void store(Level& level, const std::vector<float>& linear, bool eight_bit) const;

  int channels_ = 3;
  MipWrap wrap_ = MipWrap::Repeat;
  TexelEncoding encoding_;
  std::array<float, 256> decode_{};
  std::vector<Level> levels_;
};

}  // namespace eyetrace
