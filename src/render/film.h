// The film: accumulates weighted radiance per pixel in double precision, as linear sRGB: each
// sample's spectral radiance becomes CIE XYZ and then sRGB (core/spectrum.h) as it arrives. Each camera sample
// lands in one pixel (the filter is importance-sampled), so pixels are written by one thread.
// Non-finite samples are counted and discarded, never averaged into the image.
//
// Splats: a dispersive eye with a box filter sends a secondary wavelength's radiance to the
// pixel where that wavelength landed (spectral MIS, cameras/spectral_mis.cpp), always a pixel of
// the same tile, so still written by one thread. Splats add to a sum of their own, without
// weight: a box filter gives every sample weight 1, so the pixel's weight counts its samples
// and (sum + splat) / weight is the mean. Kept apart from the pixel's own sum so that each
// sum receives its terms in an order that does not depend on how the render was cut into
// passes (the integrator takes a tile's samples index by index, pixels within). With a smooth
// filter each wavelength splats into the pixels around where it landed, with the filter's
// weights (add_splats), again within the tile.
// bdpt's light tracing (t = 1) adds to the same splat sums through add_splat, already weighted
// by the pixel filter and its integral (render/light_splats.h), after each pass on one thread.
//
// A spectral film (pbrt-v4's Film "spectral") also keeps, per pixel, one sum per wavelength
// bucket: equal buckets over [lambda_min, lambda_max]. A sample's wavelengths are the renderer's
// (drawn from pbrt-v4's visible-wavelength density over 360-830 nm, as for the RGB film), and
// each wavelength lambda_i with density pdf_i > 0 that falls into bucket b adds
//   w * L_i / (pdf_i * N * width)          (N = 4 wavelengths per sample, width in nm)
// to that bucket's sum, so that the expected value of a sample's bucket term is the mean of
// L over the bucket, (1 / width) * integral of L over it: a constant spectrum c gives c in every
// bucket. A terminated wavelength (pdf 0) adds nothing; its hero stands for all four (pdf / 4).
// The buckets share the pixel's weight sum with R, G, B, so a pixel's bucket value is its sum
// divided by the same weight: a lost camera ray (zero radiance) darkens the buckets as it
// darkens RGB. The R, G, B channels of a spectral film are exactly those of an RGB film.
//
// Normalised splats: with a box filter a dispersive eye's wavelengths splat one by one into the
// pixels where they land, so how many of a pixel's terms each wavelength gets varies from render
// to render, and dividing by the pixel's own sample count leaves that variation in the image.
// Each wavelength therefore also brings its share of a sample (CameraRay::share: 4 times its
// spectral MIS weight; a lost camera ray's hero 4 and the others 0, which is the share of the one
// technique that made it), added as XYZ by add_share; summed over every wavelength that landed
// in the pixel its expectation is the pixel's sample count times equal_energy_xyz() (each
// wavelength's share sums to the probability that its technique traces a ray into the pixel,
// and the lost rays' heroes to the probability that it loses one). A pixel with share sums reads
// (sum + splat), taken to XYZ, divided by them channel by channel, times that white, taken back
// to linear sRGB: a ratio estimator, consistent (its bias falls as 1 / samples), in which a grey
// region's value no longer depends on which wavelengths landed there. A spectral film's buckets
// are divided likewise by their own share sums (each share as a bucket term, whose expectation
// is the sample count).
//
// A sample's colour goes through the film's pixel sensor (render/pixel_sensor.h: a camera's
// curves, white balance) when the scene names one, and is clamped as pbrt-v4's
// "maxcomponentvalue" clamps it: the sensor's responses times the imaging ratio (what pbrt-v4
// calls sensor RGB) scaled down so that the largest is the maximum, per sample and per splat,
// before they become XYZ and linear sRGB. A spectral film's buckets see the radiance clamped as
// pbrt-v4's SpectralFilm clamps it: L scaled so that its largest value, in pbrt-v4's units
// (L / the integral of y-bar), is the maximum.
#pragma once
#include <atomic>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/filter.h"
#include "core/math.h"
#include "core/spectrum.h"
#include "core/wavelength_splat.h"
#include "render/gbuffer.h"
#include "render/image_io.h"
#include "render/pixel_sensor.h"

namespace eyetrace {

struct PixelBounds {
  IVec2 lo{0}, hi{0};  // [lo, hi)
  int width() const { return hi.x - lo.x; }
  int height() const { return hi.y - lo.y; }
  size_t area() const { return size_t(width()) * size_t(height()); }
};

// pbrt's cropwindow (x0, x1, y0, y1 as fractions) to pixel bounds, as pbrt-v4 rounds them.
PixelBounds crop_to_pixels(IVec2 resolution, Vec4 crop);

// The wavelength buckets of a spectral film; count 0 is an RGB film.
struct SpectralBuckets {
  static constexpr int kMaxCount = 512;
  int count = 0;
  float lambda_min = 400.f, lambda_max = 700.f;  // nm

  bool spectral() const { return count > 0; }
  double width() const { return (double(lambda_max) - double(lambda_min)) / count; }  // nm
  double centre(int b) const { return double(lambda_min) + (b + 0.5) * width(); }
  // The bucket lambda falls into, -1 outside [lambda_min, lambda_max] (lambda_max itself is in
  // the last bucket).
  int bucket_of(float lambda) const {
    if (!(lambda >= lambda_min && lambda <= lambda_max)) return -1;
    const int b = int(double(count) * (double(lambda) - lambda_min) / (double(lambda_max) - lambda_min));
    return b < count ? b : count - 1;
  }
  // The EXR channel name of bucket b, as pbrt-v4's SpectralFilm names it (after Fichet et al.,
  // "An OpenEXR Layout for Spectral Images", JCGT 2021): "S0." and the bucket centre in nm with
  // three decimals, its '.' written as ',' (OpenEXR separates layers with '.'): "S0.409,375nm".
  std::string channel_name(int b) const;
};

// What the film does to a sample's radiance before adding it; the default is CIE 1931 XYZ to
// linear sRGB, unclamped.
struct FilmResponse {
  std::shared_ptr<const PixelSensor> sensor;                     // null: cie1931 without white balance
  float max_component = std::numeric_limits<float>::infinity();  // pbrt-v4's maxcomponentvalue
  float imaging_ratio = 1.f;  // iso / 100 * exposure time: part of the film's scale, seen by the clamp
  bool clamps() const { return max_component < std::numeric_limits<float>::infinity(); }
};

class Film {
 public:
  // `scale` multiplies every pixel (pbrt-v4's iso/exposure imaging ratio).
  Film(IVec2 resolution, PixelBounds bounds, std::unique_ptr<Filter> filter, float scale = 1.f,
       SpectralBuckets buckets = {}, FilmResponse response = {});
  IVec2 resolution() const { return resolution_; }
  const PixelBounds& bounds() const { return bounds_; }
  const Filter& filter() const { return *filter_; }
  const SpectralBuckets& buckets() const { return buckets_; }
  const FilmResponse& response() const { return response_; }
  // Makes this a gbuffer film (pbrt-v4's "gbuffer"; render/gbuffer.h): its image gets the
  // auxiliary channels, positions and normals in output_from_world's space.
  void enable_gbuffer(const AnimatedTransform& world_from_output);
  bool gbuffer() const { return gbuffer_ != nullptr; }
  // A sample's linear sRGB (before the film's scale): through the sensor, clamped.
  RGB sample_rgb(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
    if (!response_.sensor && !response_.clamps()) return sampled_to_rgb(L, lambda);
    return sensor_rgb(L, lambda);
  }

  // Adds radiance L with filter weight w to `pixel` (absolute raster coordinates).
  // Returns false (and counts it) when w, or L at a wavelength with non-zero density, or any
  // colour or bucket term it gives, is not finite: nothing of such a sample is kept.
  // `visible`: what the sample's camera ray saw, for a gbuffer film (null: nothing recorded).
  bool add_sample(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float w,
                  const VisibleSurface* visible = nullptr) {
    if (buckets_.spectral()) return add_spectral_sample(pixel, L, lambda, w);
    const RGB rgb = sample_rgb(L, lambda);
    if (!add_sample(pixel, rgb, w)) return false;
    if (gbuffer_ && visible) gbuffer_->add(index(pixel), *visible, lambda, rgb, w);
    return true;
  }
  // A sample whose radiance all went into splats (add_splats): its filter weight alone, the
  // sums add_sample with zero radiance leaves (w * 0 adds nothing, not even a sign).
  bool add_weight(IVec2 pixel, const SampledWavelengths& lambda, float w, const VisibleSurface* visible = nullptr) {
    if (gbuffer_ && visible) return add_sample(pixel, SampledSpectrum(0.f), lambda, w, visible);
    if (!std::isfinite(w)) {
      nonfinite_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    pixels_[index(pixel)].weight += w;
    return true;
  }
  // An RGB sample: adds to R, G, B and the weight, nothing to the buckets (the renderer uses it
  // for zero radiance only: a lost camera ray).
  bool add_sample(IVec2 pixel, const RGB& L, float w) {
    if (!is_finite(L) || !std::isfinite(w)) {
      nonfinite_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    Pixel& px = pixels_[index(pixel)];
    px.sum[0] += double(w) * L.r;
    px.sum[1] += double(w) * L.g;
    px.sum[2] += double(w) * L.b;
    px.weight += w;
    const double wy = double(w) * double(luminance(L));
    px.sum_y2 += wy * wy;
    return true;
  }
  // Adds radiance L, already weighted, to `pixel`'s splat sums (R, G, B and, for a spectral
  // film, the buckets). Returns false (and counts it) when any term is not finite.
  bool add_splat(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda);
  // The same for a block of pixels, pixel (first.x + c, first.y + r) receiving L times
  // s.wx[c] * s.wy[r] (a dispersive eye's wavelength splatted with a smooth filter's weights):
  // the colour is formed (and clamped) once, for L.
  bool add_splats(const WavelengthSplat& s, const SampledSpectrum& L, const SampledWavelengths& lambda);
  // Every wavelength k of a sample over its own block splats[k] (nx 0: nowhere): add_splats of
  // L[k] alone for each, the colour formed per wavelength (wavelength_to_rgb) when the film
  // neither senses, clamps nor keeps buckets. A wavelength with a non-finite term is counted
  // and dropped, the others kept.
  void add_wavelength_splats(const WavelengthSplat* splats, const SampledSpectrum& L, const SampledWavelengths& lambda);
  // Adds the XYZ of a sample's wavelengths' shares (CameraRay::share, one value per wavelength,
  // as sampled_to_xyz forms a radiance's) to `pixel`'s share sums (see the top of the file).
  // Returns false (and counts it) when a term is not finite.
  bool add_share(IVec2 pixel, const SampledSpectrum& share, const SampledWavelengths& lambda);
  RGB pixel_value(IVec2 pixel) const;
  // The mean spectral radiance of bucket b at `pixel` (times the film's scale); 0 before any sample.
  float bucket_value(IVec2 pixel, int b) const;
  // The crop region, top row first: R, G, B, then (spectral film) one channel per bucket, or
  // (gbuffer film) the auxiliary channels, named.
  Image image() const;
  // image() in parts: the image's size and channels with every value 0; the values of the
  // pixels in `region` (absolute raster coordinates, inside bounds()) written into it; one
  // pixel's channels (3 + buckets().count, or 3 + GBuffer::kChannels) written to `out`.
  Image blank_image() const;
  void fill_image(const PixelBounds& region, Image& image) const;
  void pixel_channels(IVec2 pixel, float* out) const;
  // Header attributes that describe the channels (the spectral layout's version and units).
  std::map<std::string, std::string> image_metadata() const;
  uint64_t nonfinite_samples() const { return nonfinite_; }

  // What a pixel's own samples (not splats) say about its mean luminance: the sums of w Y and
  // (w Y)^2 over its samples (Y the luminance of the sample's linear sRGB, before the film's
  // scale) and of the weights w. Adaptive sampling estimates each pixel's error from them.
  struct Moments {
    double sum_y = 0, sum_y2 = 0, weight = 0;
  };
  Moments moments(IVec2 pixel) const;

  // The exact accumulators, per pixel row-major over bounds(): the weighted r, g, b sums, the
  // weight sum, the r, g, b splat sums, the sum of squared weighted luminances and the X, Y, Z
  // share sums, then (spectral film) the weighted sum of each bucket, each bucket's splat sum and
  // each bucket's share sum: kAccumulatorsPerPixel + kBucketAccumulators buckets().count doubles
  // per pixel. A checkpoint stores them, and a film restored from them continues bit for bit as
  // if it had never stopped.
  std::vector<double> accumulators() const;
  static constexpr size_t kAccumulatorsPerPixel = 11;
  static constexpr size_t kBucketAccumulators = 3;  // a bucket's sum, splat sum and share sum
  size_t accumulators_per_pixel() const { return kAccumulatorsPerPixel + kBucketAccumulators * size_t(buckets_.count); }
  // Throws std::invalid_argument unless `acc` holds accumulators_per_pixel() values per pixel.
  void restore(const std::vector<double>& acc, uint64_t nonfinite_samples);
  // One pixel's accumulators (index row-major over bounds()), as accumulators() lays them out:
  // accumulators_per_pixel() values to or from `values`.
  void copy_accumulators(size_t pixel_index, double* values) const;
  void set_accumulators(size_t pixel_index, const double* values);

 private:
  struct Pixel {
    double sum[3] = {0, 0, 0};
    double weight = 0;
    double splat[3] = {0, 0, 0};
    double sum_y2 = 0;            // of (w Y)^2 over the pixel's own samples
    double share[3] = {0, 0, 0};  // XYZ of the wavelengths' shares (add_share); 0: none
  };
  RGB sensor_rgb(const SampledSpectrum& L, const SampledWavelengths& lambda) const;
  RGB normalised_value(const Pixel& px) const;
  SampledSpectrum clamped_radiance(const SampledSpectrum& L, const SampledWavelengths& lambda) const;
  void splat_rgb(const WavelengthSplat& s, const RGB& rgb);
  bool add_spectral_sample(IVec2 pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float w);
  bool bucket_terms(const SampledSpectrum& L, const SampledWavelengths& lambda, float w, int* bucket,
                    double* term) const;
  size_t index(IVec2 p) const { return size_t(p.y - bounds_.lo.y) * bounds_.width() + (p.x - bounds_.lo.x); }
  IVec2 resolution_;
  PixelBounds bounds_;
  std::unique_ptr<Filter> filter_;
  float scale_;
  SpectralBuckets buckets_;
  FilmResponse response_;
  std::unique_ptr<GBuffer> gbuffer_;
  std::vector<Pixel> pixels_;
  std::vector<double>
      bucket_sums_;  // per pixel, in pixel order: buckets_.count sums, as many splat sums and share sums
  std::atomic<uint64_t> nonfinite_{0};
};

}  // namespace eyetrace
