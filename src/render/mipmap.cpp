#include "render/mipmap.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "core/srgb.h"

namespace eyetrace {

namespace {

// pbrt-v4's EWA weights: a Gaussian of the squared ellipse radius r2 in [0, 1], alpha = 2,
// less its value at the rim so that the weight falls to 0 there; 128 entries.
constexpr int kMipEwaTableSize = 128;
const std::array<float, kMipEwaTableSize>& mip_ewa_weights() {
  static const std::array<float, kMipEwaTableSize> table = [] {
    std::array<float, kMipEwaTableSize> t{};
    for (int i = 0; i < kMipEwaTableSize; ++i) {
      double r2 = double(i) / double(kMipEwaTableSize - 1);
      t[i] = float(std::exp(-2. * r2) - std::exp(-2.));
    }
    return t;
  }();
  return table;
}

bool is_power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }
int round_up_power_of_two(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

// pbrt-v4's Lanczos resampling weights (windowed sinc, radius 2, tau 2) of the four source
// pixels nearest each of `new_size` pixels, normalised to sum 1.
struct LanczosWeight {
  int first = 0;
  float w[4] = {};
};
float lanczos_sinc(float x) { return std::abs(x) < 1e-5f ? 1.f : std::sin(kPi * x) / (kPi * x); }
std::vector<LanczosWeight> lanczos_weights(int old_size, int new_size) {
  std::vector<LanczosWeight> weights(static_cast<size_t>(new_size));
  constexpr float kRadius = 2.f, kTau = 2.f;
  for (int i = 0; i < new_size; ++i) {
    LanczosWeight& r = weights[size_t(i)];
    float centre = (float(i) + 0.5f) * float(old_size) / float(new_size);
    r.first = int(std::floor(centre - kRadius + 0.5f));
    float sum = 0.f;
    for (int j = 0; j < 4; ++j) {
      float x = float(r.first + j) + 0.5f - centre;
      r.w[j] = std::abs(x) > kRadius ? 0.f : lanczos_sinc(x) * lanczos_sinc(x / kTau);
      sum += r.w[j];
    }
    for (float& w : r.w) w /= sum;
  }
  return weights;
}

// The nearest byte to v * 255 (halves up), 0 for NaN.
uint8_t texel_byte(float v) {
  const float x = v * 255.f + 0.5f;
  return x >= 255.f ? uint8_t(255) : x > 0.f ? uint8_t(x) : uint8_t(0);
}

// A texel's coordinates under the wrap mode; false when it is black there.
bool wrap_texel(MipWrap wrap, int& x, int& y, int width, int height) {
  switch (wrap) {
    case MipWrap::Repeat:
      x = ((x % width) + width) % width;
      y = ((y % height) + height) % height;
      return true;
    case MipWrap::Clamp:
      x = std::clamp(x, 0, width - 1);
      y = std::clamp(y, 0, height - 1);
      return true;
    case MipWrap::Black: break;
  }
  return x >= 0 && x < width && y >= 0 && y < height;
}

// pbrt-v4 resizes an image whose sides are not powers of two up to powers of two before
// building the levels (rows, then columns), sampling beyond the edges by the wrap mode;
// negative lobes of the sinc are clamped at 0.
std::vector<float> resize_up_to_powers_of_two(const std::vector<float>& img, int w, int h, int n, int w2, int h2,
                                              MipWrap wrap) {
  const auto wx = lanczos_weights(w, w2), wy = lanczos_weights(h, h2);
  auto at = [&](const std::vector<float>& im, int iw, int ih, int x, int y, int c) {
    return wrap_texel(wrap, x, y, iw, ih) ? im[(size_t(y) * iw + x) * n + c] : 0.f;
  };
  std::vector<float> rows(size_t(w2) * h * n), out(size_t(w2) * h2 * n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w2; ++x)
      for (int c = 0; c < n; ++c) {
        float s = 0.f;
        for (int j = 0; j < 4; ++j) s += wx[size_t(x)].w[j] * at(img, w, h, wx[size_t(x)].first + j, y, c);
        rows[(size_t(y) * w2 + x) * n + c] = s;
      }
  for (int y = 0; y < h2; ++y)
    for (int x = 0; x < w2; ++x)
      for (int c = 0; c < n; ++c) {
        float s = 0.f;
        for (int j = 0; j < 4; ++j) s += wy[size_t(y)].w[j] * at(rows, w2, h, x, wy[size_t(y)].first + j, c);
        out[(size_t(y) * w2 + x) * n + c] = std::max(0.f, s);
      }
  return out;
}

// The next level: each texel the 2x2 box average of the level below's linear values (`at` of
// an index into its interleaved texels), a side of one texel averaging its texel with itself,
// as pbrt-v4's GeneratePyramid does.
template <typename At>
std::vector<float> half_size_level(int w, int h, int n, const At& at) {
  const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
  std::vector<float> next(size_t(nw) * nh * n);
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      const size_t x0 = 2 * x, x1 = std::min(2 * x + 1, w - 1), y0 = 2 * y, y1 = std::min(2 * y + 1, h - 1);
      for (int c = 0; c < n; ++c)
        next[(size_t(y) * nw + x) * n + c] = (at((y0 * w + x0) * n + c) + at((y0 * w + x1) * n + c) +
                                              at((y1 * w + x0) * n + c) + at((y1 * w + x1) * n + c)) /
                                             4.f;
    }
  return next;
}

}  // namespace

float TexelEncoding::decode(float v) const {
  switch (kind) {
    case Kind::SRGB: return srgb_to_linear(v);
    case Kind::Gamma: return std::pow(std::max(v, 0.f), gamma);
    case Kind::Linear: break;
  }
  return v;
}

float TexelEncoding::encode(float v) const {
  switch (kind) {
    case Kind::SRGB: return linear_to_srgb(v);
    case Kind::Gamma: return std::pow(std::max(v, 0.f), 1.f / gamma);
    case Kind::Linear: break;
  }
  return v;
}

MipMap::MipMap(const Image& image, int channels, bool eight_bit, TexelEncoding encoding, MipWrap wrap)
    : channels_(channels), wrap_(wrap), encoding_(encoding) {
  const int n = channels_;
  const size_t texels = size_t(image.width) * image.height;
  auto value = [&](size_t p, int c) {
    const float v = image.pixels[p * size_t(image.channels) + size_t(c)];
    return std::isfinite(v) ? v : 0.f;
  };
  if (eight_bit) {
    std::vector<uint8_t> bytes(texels * n);
    for (size_t p = 0; p < texels; ++p)
      for (int c = 0; c < n; ++c) bytes[p * n + c] = texel_byte(value(p, c));
    build_from_bytes(std::move(bytes), image.width, image.height);
    return;
  }
  std::vector<float> linear(texels * n);
  for (size_t p = 0; p < texels; ++p)
    for (int c = 0; c < n; ++c) linear[p * n + c] = encoding.decode(value(p, c));
  build(std::move(linear), image.width, image.height, false);
}

MipMap::MipMap(std::vector<uint8_t> samples, int width, int height, int stride, int channels, TexelEncoding encoding,
               MipWrap wrap)
    : channels_(channels), wrap_(wrap), encoding_(encoding) {
  if (stride != channels) {  // texel t's samples move down to t * channels, never past unread ones
    const size_t texels = size_t(width) * height;
    for (size_t t = 0; t < texels; ++t)
      for (int c = 0; c < channels; ++c) samples[t * channels + c] = samples[t * stride + c];
    samples.resize(texels * channels);
  }
  build_from_bytes(std::move(samples), width, height);
}

void MipMap::build_from_bytes(std::vector<uint8_t> bytes, int w, int h) {
  for (int i = 0; i < 256; ++i) decode_[size_t(i)] = encoding_.decode(float(i) / 255.f);
  if (is_power_of_two(w) && is_power_of_two(h)) {
    // Level 0 keeps the file's bytes; level 1 averages their decoded values.
    std::vector<float> next;
    if (w > 1 || h > 1) next = half_size_level(w, h, channels_, [&](size_t i) { return decode_[bytes[i]]; });
    levels_.push_back(Level{w, h, std::move(bytes), {}});
    if (!next.empty()) build(std::move(next), std::max(1, w / 2), std::max(1, h / 2), true);
    return;
  }
  std::vector<float> linear(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) linear[i] = decode_[bytes[i]];
  build(std::move(linear), w, h, true);
}

void MipMap::build(std::vector<float> linear, int w, int h, bool eight_bit) {
  const int n = channels_;
  if (!is_power_of_two(w) || !is_power_of_two(h)) {
    const int w2 = round_up_power_of_two(w), h2 = round_up_power_of_two(h);
    linear = resize_up_to_powers_of_two(linear, w, h, n, w2, h2, wrap_);
    w = w2, h = h2;
  }
  for (;;) {
    Level l{w, h, {}, {}};
    store(l, linear, eight_bit);
    levels_.push_back(std::move(l));
    if (w == 1 && h == 1) return;
    linear = half_size_level(w, h, n, [&](size_t i) { return linear[i]; });
    w = std::max(1, w / 2), h = std::max(1, h / 2);
  }
}

void MipMap::store(Level& level, const std::vector<float>& linear, bool eight_bit) const {
  if (!eight_bit) {
    level.floats = linear;
    return;
  }
  level.bytes.resize(linear.size());
  for (size_t i = 0; i < linear.size(); ++i) level.bytes[i] = texel_byte(encoding_.encode(linear[i]));
}

size_t MipMap::bytes() const {
  size_t b = 0;
  for (const Level& l : levels_) b += l.bytes.size() + l.floats.size() * sizeof(float);
  return b;
}

float MipMap::texel(int level, int x, int y, int c) const {
  const Level& l = levels_[size_t(level)];
  if (!wrap_texel(wrap_, x, y, l.width, l.height)) return 0.f;
  return stored(l, (size_t(y) * l.width + x) * channels_ + c);
}

void MipMap::bilerp(int level, Vec2 st, float* out) const {
  const Level& l = levels_[size_t(level)];
  const float x = st.x * float(l.width) - 0.5f, y = st.y * float(l.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float dx = x - fx, dy = y - fy;
  const int xi = int(fx), yi = int(fy);
  const float w00 = (1.f - dx) * (1.f - dy), w10 = dx * (1.f - dy), w01 = (1.f - dx) * dy, w11 = dx * dy;
  if (xi >= 0 && yi >= 0 && xi + 1 < l.width && yi + 1 < l.height) {  // inside: no wrapping
    const size_t i00 = (size_t(yi) * l.width + xi) * channels_, i01 = i00 + size_t(l.width) * channels_;
    for (int c = 0; c < channels_; ++c)
      out[c] = w00 * stored(l, i00 + c) + w10 * stored(l, i00 + channels_ + c) + w01 * stored(l, i01 + c) +
               w11 * stored(l, i01 + channels_ + c);
    return;
  }
  for (int c = 0; c < channels_; ++c)
    out[c] = w00 * texel(level, xi, yi, c) + w10 * texel(level, xi + 1, yi, c) + w01 * texel(level, xi, yi + 1, c) +
             w11 * texel(level, xi + 1, yi + 1, c);
}

void MipMap::filter(MipFilter f, float max_anisotropy, Vec2 st, Vec2 dst0, Vec2 dst1, float* out) const {
  std::fill(out, out + channels_, 0.f);
  if (!std::isfinite(st.x) || !std::isfinite(st.y)) return;
  // Far outside [0, 1] only the wrap mode matters: a repeating image is periodic, the others
  // are black or their edge there; this keeps texel indices far from int's range.
  if (wrap_ == MipWrap::Repeat)
    st -= glm::floor(st);
  else
    st = glm::clamp(st, Vec2(-4.f), Vec2(5.f));
  if (!std::isfinite(dst0.x + dst0.y + dst1.x + dst1.y)) dst0 = dst1 = Vec2(0.f);
  // A footprint of more than the image already filters it whole; bounding it keeps the EWA
  // axes' squared lengths finite.
  dst0 = glm::clamp(dst0, Vec2(-1e4f), Vec2(1e4f));
  dst1 = glm::clamp(dst1, Vec2(-1e4f), Vec2(1e4f));
  const int top = levels() - 1;

  if (f != MipFilter::Ewa) {
    const float width = 2.f * std::max({std::abs(dst0.x), std::abs(dst0.y), std::abs(dst1.x), std::abs(dst1.y)});
    // pbrt-v4 takes log2 of max(width, 1e-8); any width below 2^-top picks level 0, which a
    // zero footprint (hits without ray differentials) reaches without the logarithm.
    const float level = width > 0.f ? float(top) + std::log2(std::max(width, 1e-8f)) : -1.f;
    if (level >= float(top)) {
      for (int c = 0; c < channels_; ++c) out[c] = texel(top, 0, 0, c);
      return;
    }
    const int il = std::max(0, int(std::floor(level)));
    if (f == MipFilter::Point) {
      const Level& l = levels_[size_t(il)];
      const int x = int(std::round(st.x * float(l.width) - 0.5f)), y = int(std::round(st.y * float(l.height) - 0.5f));
      for (int c = 0; c < channels_; ++c) out[c] = texel(il, x, y, c);
      return;
    }
    // Trilinear blends two levels, except below level 1, where pbrt-v4 filters level 0 alone.
    bilerp(il, st, out);
    if (f == MipFilter::Trilinear && il > 0) {
      float upper[3];
      bilerp(il + 1, st, upper);
      const float t = level - float(il);
      for (int c = 0; c < channels_; ++c) out[c] = (1.f - t) * out[c] + t * upper[c];
    }
    return;
  }

  // EWA: the longer axis first; an ellipse more eccentric than max_anisotropy is widened along
  // its shorter axis (blurrier, but bounded work); the level from the shorter axis.
  if (glm::dot(dst0, dst0) < glm::dot(dst1, dst1)) std::swap(dst0, dst1);
  const float longer = glm::length(dst0);
  float shorter = glm::length(dst1);
  if (shorter * max_anisotropy < longer && shorter > 0.f) {
    const float scale = longer / (shorter * max_anisotropy);
    dst1 *= scale;
    shorter *= scale;
  }
  if (shorter == 0.f) {
    bilerp(0, st, out);
    return;
  }
  const float lod = std::clamp(float(top) + std::log2(shorter), 0.f, float(levels()));
  const int il = int(std::floor(lod));
  float upper[3];
  ewa(il, st, dst0, dst1, out);
  ewa(il + 1, st, dst0, dst1, upper);
  const float t = lod - float(il);
  for (int c = 0; c < channels_; ++c) out[c] = (1.f - t) * out[c] + t * upper[c];
}

void MipMap::ewa(int level, Vec2 st, Vec2 dst0, Vec2 dst1, float* out) const {
  if (level >= levels()) {
    for (int c = 0; c < channels_; ++c) out[c] = texel(levels() - 1, 0, 0, c);
    return;
  }
  const Vec2 res(resolution(level));
  st = st * res - 0.5f;
  dst0 *= res;
  dst1 *= res;
  // The ellipse's implicit form A s^2 + B s t + C t^2 < 1; the +1s make it cover at least a
  // texel's radius, so some texel always lies inside and the weights never sum to 0.
  float A = dst0.y * dst0.y + dst1.y * dst1.y + 1.f;
  float B = -2.f * (dst0.x * dst0.y + dst1.x * dst1.y);
  float C = dst0.x * dst0.x + dst1.x * dst1.x + 1.f;
  const float inv_f = 1.f / (A * C - B * B * 0.25f);
  A *= inv_f, B *= inv_f, C *= inv_f;
  const float det = 4.f * A * C - B * B, inv_det = 1.f / det;
  const float u = std::sqrt(std::max(0.f, det * C)), v = std::sqrt(std::max(0.f, A * det));
  const int s0 = int(std::ceil(st.x - 2.f * inv_det * u)), s1 = int(std::floor(st.x + 2.f * inv_det * u));
  const int t0 = int(std::ceil(st.y - 2.f * inv_det * v)), t1 = int(std::floor(st.y + 2.f * inv_det * v));
  const auto& weights = mip_ewa_weights();
  float sum[3] = {0.f, 0.f, 0.f}, total = 0.f;
  for (int it = t0; it <= t1; ++it) {
    const float tt = float(it) - st.y;
    for (int is = s0; is <= s1; ++is) {
      const float ss = float(is) - st.x;
      const float r2 = A * ss * ss + B * ss * tt + C * tt * tt;
      if (!(r2 < 1.f)) continue;
      const float w = weights[size_t(std::clamp(int(r2 * kMipEwaTableSize), 0, kMipEwaTableSize - 1))];
      for (int c = 0; c < channels_; ++c) sum[c] += w * texel(level, is, it, c);
      total += w;
    }
  }
  for (int c = 0; c < channels_; ++c) out[c] = total > 0.f ? sum[c] / total : 0.f;
}

}  // namespace eyetrace
