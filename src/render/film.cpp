#include "render/film.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace eyetrace {

PixelBounds crop_to_pixels(IVec2 res, Vec4 crop) {
  PixelBounds b;
  b.lo = IVec2(int(std::ceil(res.x * crop[0])), int(std::ceil(res.y * crop[2])));
  b.hi = IVec2(int(std::ceil(res.x * crop[1])), int(std::ceil(res.y * crop[3])));
  b.lo = glm::clamp(b.lo, IVec2(0), res);
  b.hi = glm::clamp(b.hi, b.lo, res);
  return b;
}

std::string SpectralBuckets::channel_name(int b) const {
  std::string lambda = fmt::format("{:.3f}nm", centre(b));
  std::replace(lambda.begin(), lambda.end(), '.', ',');
  return "S0." + lambda;
}

Film::Film(IVec2 resolution, PixelBounds bounds, std::unique_ptr<Filter> filter, float scale, SpectralBuckets buckets,
           FilmResponse response)
    : resolution_(resolution),
      bounds_(bounds),
      filter_(std::move(filter)),
      scale_(scale),
      buckets_(buckets),
      response_(std::move(response)),
      pixels_(bounds.area()) {
  if (buckets_.count < 0 || buckets_.count > SpectralBuckets::kMaxCount ||
      (buckets_.spectral() && !(buckets_.lambda_min < buckets_.lambda_max)))
    throw std::invalid_argument("Film: invalid spectral buckets");
  if (!(response_.max_component > 0.f) || !(response_.imaging_ratio > 0.f) || !std::isfinite(response_.imaging_ratio))
    throw std::invalid_argument("Film: the maximum component and the imaging ratio must be positive");
  bucket_sums_.assign(bounds.area() * kBucketAccumulators * size_t(buckets_.count), 0.0);
}

void Film::enable_gbuffer(const AnimatedTransform& world_from_output) {
  if (buckets_.spectral()) throw std::invalid_argument("Film: a spectral film cannot also be a gbuffer film");
  gbuffer_ = std::make_unique<GBuffer>(bounds_.area(), world_from_output);
}

RGB Film::sensor_rgb(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
  Vec3 s = response_.sensor ? response_.sensor->responses(L, lambda) : sampled_to_xyz(L, lambda);
  // pbrt-v4 clamps the sensor RGB after the imaging ratio; the film applies that ratio at the
  // end, so the responses are compared with max / ratio. A NaN maximum compares false and an
  // infinite one gives NaN: both are then rejected as non-finite by the caller.
  const float m = max_component(s) * response_.imaging_ratio;
  if (m > response_.max_component) s *= response_.max_component / m;
  return xyz_to_linear_srgb(response_.sensor ? response_.sensor->xyz(s) : s);
}

SampledSpectrum Film::clamped_radiance(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
  if (!response_.clamps()) return L;
  // pbrt-v4's SpectralFilm compares L's largest value with the maximum in its own units, in
  // which lights have a y-bar integral of 1; ours have a y-bar integral of cie_y_integral().
  const SampledSpectrum pdf = lambda.pdf();
  float m = 0.f;
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (pdf[i] != 0.f) m = std::max(m, L[i]);
  const float limit = response_.max_component * cie_y_integral();
  if (!(m > limit)) return L;
  SampledSpectrum c = L;
  for (int i = 0; i < kSpectrumSamples; ++i) c[i] *= limit / m;
  return c;
}

// A sample's bucket terms, w L_i / (pdf_i N width) per counting wavelength (bucket -1: none);
// false when any of them, or L at a counting wavelength, is not finite.
bool Film::bucket_terms(const SampledSpectrum& L, const SampledWavelengths& lambda, float w, int* bucket,
                        double* term) const {
  const SampledSpectrum pdf = lambda.pdf();
  const double norm = 1.0 / (double(kSpectrumSamples) * buckets_.width());
  bool finite = true;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    bucket[i] = -1;
    term[i] = 0.0;
    if (pdf[i] == 0.f) continue;  // terminated: stands for nothing
    if (!std::isfinite(L[i])) finite = false;
    bucket[i] = buckets_.bucket_of(lambda[i]);
    if (bucket[i] < 0) continue;
    term[i] = double(w) * double(L[i]) / double(pdf[i]) * norm;
    if (!std::isfinite(term[i])) finite = false;
  }
  return finite;
}

bool Film::add_spectral_sample(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float w) {
  const RGB rgb = sample_rgb(L, lambda);
  // Every term first, so that a sample with any non-finite part changes nothing.
  int bucket[kSpectrumSamples];
  double term[kSpectrumSamples];
  if (!(bucket_terms(clamped_radiance(L, lambda), lambda, w, bucket, term) && is_finite(rgb) && std::isfinite(w))) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  const size_t i_px = index(pixel);
  Pixel& px = pixels_[i_px];
  px.sum[0] += double(w) * rgb.r;
  px.sum[1] += double(w) * rgb.g;
  px.sum[2] += double(w) * rgb.b;
  px.weight += w;
  const double wy = double(w) * double(luminance(rgb));
  px.sum_y2 += wy * wy;
  double* sums = &bucket_sums_[i_px * kBucketAccumulators * size_t(buckets_.count)];
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (bucket[i] >= 0) sums[bucket[i]] += term[i];
  return true;
}

// One pixel with weight 1: the same sums, bit for bit (w = 1 * 1 multiplies exactly).
bool Film::add_splat(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda) {
  WavelengthSplat one;
  one.first = pixel;
  one.nx = one.ny = 1;
  one.wx[0] = one.wy[0] = 1.f;
  return add_splats(one, L, lambda);
}

bool Film::add_splats(const WavelengthSplat& s, const SampledSpectrum& L, const SampledWavelengths& lambda) {
  const RGB rgb = sample_rgb(L, lambda);
  int bucket[kSpectrumSamples];
  double term[kSpectrumSamples];
  if (!(is_finite(rgb) &&
        (!buckets_.spectral() || bucket_terms(clamped_radiance(L, lambda), lambda, 1.f, bucket, term)))) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  splat_rgb(s, rgb);
  if (!buckets_.spectral()) return true;
  for (int r = 0; r < s.ny; ++r)
    for (int c = 0; c < s.nx; ++c) {
      const double w = double(s.wx[c]) * double(s.wy[r]);
      double* splats = &bucket_sums_[(index(s.first + IVec2(c, r)) * kBucketAccumulators + 1) * size_t(buckets_.count)];
      for (int i = 0; i < kSpectrumSamples; ++i)
        if (bucket[i] >= 0) splats[bucket[i]] += w * term[i];
    }
  return true;
}

void Film::splat_rgb(const WavelengthSplat& s, const RGB& rgb) {
  for (int r = 0; r < s.ny; ++r) {
    Pixel* row = &pixels_[index(s.first + IVec2(0, r))];
    const double wy = double(s.wy[r]);
    for (int c = 0; c < s.nx; ++c) {
      const double w = double(s.wx[c]) * wy;
      row[c].splat[0] += w * rgb.r;
      row[c].splat[1] += w * rgb.g;
      row[c].splat[2] += w * rgb.b;
    }
  }
}

void Film::add_wavelength_splats(const WavelengthSplat* splats, const SampledSpectrum& L,
                                 const SampledWavelengths& lambda) {
  const bool direct = !buckets_.spectral() && !response_.sensor && !response_.clamps();
  const SampledSpectrum pdf = lambda.pdf();
  for (int k = 0; k < kSpectrumSamples; ++k) {
    if (splats[k].nx == 0 || L[k] == 0.f) continue;
    if (!direct) {
      SampledSpectrum one(0.f);
      one[k] = L[k];
      add_splats(splats[k], one, lambda);
      continue;
    }
    if (pdf[k] == 0.f) continue;  // a terminated wavelength counts for nothing (sampled_to_xyz)
    const RGB rgb = wavelength_to_rgb(lambda[k], L[k] / pdf[k]);
    if (!is_finite(rgb)) {
      nonfinite_.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    splat_rgb(splats[k], rgb);
  }
}

bool Film::add_share(IVec2 pixel, const SampledSpectrum& share, const SampledWavelengths& lambda) {
  const Vec3 xyz = sampled_to_xyz(share, lambda);
  if (!(std::isfinite(xyz.x) && std::isfinite(xyz.y) && std::isfinite(xyz.z))) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  int bucket[kSpectrumSamples];
  double term[kSpectrumSamples];
  if (buckets_.spectral() && !bucket_terms(share, lambda, 1.f, bucket, term)) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  const size_t i_px = index(pixel);
  Pixel& px = pixels_[i_px];
  for (int c = 0; c < 3; ++c) px.share[c] += double(xyz[c]);
  if (!buckets_.spectral()) return true;
  double* shares = &bucket_sums_[(i_px * kBucketAccumulators + 2) * size_t(buckets_.count)];
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (bucket[i] >= 0) shares[bucket[i]] += term[i];
  return true;
}

namespace {

// xyz_to_linear_srgb as a matrix (it is linear), and its inverse.
const glm::dmat3& srgb_from_xyz() {
  static const glm::dmat3 m = [] {
    glm::dmat3 a;
    for (int c = 0; c < 3; ++c) {
      Vec3 e(0.f);
      e[c] = 1.f;
      const RGB v = xyz_to_linear_srgb(e);
      a[c] = glm::dvec3(v.r, v.g, v.b);
    }
    return a;
  }();
  return m;
}

}  // namespace

// (sum + splat) / share sums per XYZ channel, times the white they estimate (see film.h).
RGB Film::normalised_value(const Pixel& px) const {
  static const glm::dmat3 xyz_from_srgb = glm::inverse(srgb_from_xyz());
  const glm::dvec3 sum =
      xyz_from_srgb * glm::dvec3(px.sum[0] + px.splat[0], px.sum[1] + px.splat[1], px.sum[2] + px.splat[2]);
  const glm::dvec3 xyz = sum / glm::dvec3(px.share[0], px.share[1], px.share[2]) * glm::dvec3(equal_energy_xyz());
  const glm::dvec3 rgb = srgb_from_xyz() * xyz * double(scale_);
  return RGB(float(rgb.x), float(rgb.y), float(rgb.z));
}

RGB Film::pixel_value(IVec2 p) const {
  const Pixel& px = pixels_[index(p)];
  if (px.weight == 0) return RGB(0.f);
  if (px.share[0] > 0 && px.share[1] > 0 && px.share[2] > 0) return normalised_value(px);
  double k = scale_ / px.weight;
  return RGB(float((px.sum[0] + px.splat[0]) * k), float((px.sum[1] + px.splat[1]) * k),
             float((px.sum[2] + px.splat[2]) * k));
}

float Film::bucket_value(IVec2 p, int b) const {
  const size_t i = index(p);
  const double weight = pixels_[i].weight;
  if (weight == 0) return 0.f;
  const size_t n = size_t(buckets_.count);
  const double* sums = &bucket_sums_[i * kBucketAccumulators * n];
  // Normalised splats: the bucket's share sum, whose expectation is the sample count (film.h).
  const double share = sums[2 * n + size_t(b)];
  if (pixels_[i].share[1] > 0) return share > 0 ? float((sums[b] + sums[n + size_t(b)]) * (scale_ / share)) : 0.f;
  return float((sums[b] + sums[n + size_t(b)]) * (scale_ / weight));
}

Film::Moments Film::moments(IVec2 p) const {
  const Pixel& px = pixels_[index(p)];
  // The weights of core/math.h's luminance(), applied to the sums in double precision.
  return {0.2126 * px.sum[0] + 0.7152 * px.sum[1] + 0.0722 * px.sum[2], px.sum_y2, px.weight};
}

Image Film::image() const {
  Image img = blank_image();
  fill_image(bounds_, img);
  return img;
}

Image Film::blank_image() const {
  Image img;
  img.width = bounds_.width();
  img.height = bounds_.height();
  img.channels = 3 + buckets_.count + (gbuffer_ ? GBuffer::kChannels : 0);
  if (buckets_.spectral()) {
    img.channel_names = {"R", "G", "B"};
    for (int b = 0; b < buckets_.count; ++b) img.channel_names.push_back(buckets_.channel_name(b));
  }
  if (gbuffer_) {
    img.channel_names = {"R", "G", "B"};
    for (const std::string& n : GBuffer::channel_names()) img.channel_names.push_back(n);
  }
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  return img;
}

void Film::fill_image(const PixelBounds& region, Image& image) const {
  for (int y = region.lo.y; y < region.hi.y; ++y)
    for (int x = region.lo.x; x < region.hi.x; ++x)
      pixel_channels(IVec2(x, y), &image.at(x - bounds_.lo.x, y - bounds_.lo.y, 0));
}

void Film::pixel_channels(IVec2 pixel, float* out) const {
  const RGB v = pixel_value(pixel);
  for (int c = 0; c < 3; ++c) out[c] = std::isfinite(v[c]) ? v[c] : 0.f;
  for (int b = 0; b < buckets_.count; ++b) {
    const float s = bucket_value(pixel, b);
    out[3 + b] = std::isfinite(s) ? s : 0.f;
  }
  if (gbuffer_) gbuffer_->channels(index(pixel), pixels_[index(pixel)].weight, scale_, out + 3);
}

std::map<std::string, std::string> Film::image_metadata() const {
  if (!buckets_.spectral()) return {};
  // As pbrt-v4's SpectralFilm writes them (the layout of Fichet et al. 2021), and the buckets
  // themselves, since the channel names give only their centres.
  return {
      {"spectralLayoutVersion", "1.0"},
      {"emissiveUnits", "W.m^-2.sr^-1"},
      {"eyetrace:spectral_buckets", fmt::format("{} {} {}", buckets_.count, buckets_.lambda_min, buckets_.lambda_max)}};
}

void Film::copy_accumulators(size_t i, double* out) const {
  const Pixel& p = pixels_[i];
  const double own[kAccumulatorsPerPixel] = {p.sum[0],   p.sum[1], p.sum[2],   p.weight,   p.splat[0], p.splat[1],
                                             p.splat[2], p.sum_y2, p.share[0], p.share[1], p.share[2]};
  std::copy(own, own + kAccumulatorsPerPixel, out);
  const size_t n = kBucketAccumulators * size_t(buckets_.count);
  std::copy(bucket_sums_.begin() + std::ptrdiff_t(i * n), bucket_sums_.begin() + std::ptrdiff_t((i + 1) * n),
            out + kAccumulatorsPerPixel);
}

void Film::set_accumulators(size_t i, const double* a) {
  pixels_[i] = Pixel{{a[0], a[1], a[2]}, a[3], {a[4], a[5], a[6]}, a[7], {a[8], a[9], a[10]}};
  const size_t n = kBucketAccumulators * size_t(buckets_.count);
  std::copy(a + kAccumulatorsPerPixel, a + kAccumulatorsPerPixel + n, bucket_sums_.begin() + std::ptrdiff_t(i * n));
}

std::vector<double> Film::accumulators() const {
  const size_t per = accumulators_per_pixel();
  std::vector<double> acc(pixels_.size() * per);
  for (size_t i = 0; i < pixels_.size(); ++i) copy_accumulators(i, &acc[i * per]);
  return acc;
}

void Film::restore(const std::vector<double>& acc, uint64_t nonfinite_samples) {
  const size_t per = accumulators_per_pixel();
  if (acc.size() != pixels_.size() * per) throw std::invalid_argument("Film::restore: wrong number of accumulators");
  for (size_t i = 0; i < pixels_.size(); ++i) set_accumulators(i, &acc[per * i]);
  nonfinite_ = nonfinite_samples;
}

}  // namespace eyetrace
