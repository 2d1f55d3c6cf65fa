#include "render/gbuffer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/spectrum.h"

namespace eyetrace {

namespace {
// Offsets of the sums in a pixel's accumulators.
enum : size_t {
  kP = 0,
  kN = 3,
  kNs = 6,
  kUv = 9,
  kAlbedo = 11,
  kWeight = 14,
  kCount = 15,
  kMean = 16,
  kM2 = 19,
  kDz = 22
};

// The ray of `sample` moved by one pixel along `axis`, as pbrt-v4's differential (origin and
// direction per pixel, from a +1 or, failing that, a -1 pixel step) scaled by `scale`; empty
// when both steps lose the ray.
std::optional<Ray> differential_ray(const Camera& camera, CameraSample sample, const Ray& ray, int axis, float scale) {
  for (float step : {1.f, -1.f}) {
    CameraSample shifted = sample;
    shifted.p_film[axis] += step;
    SampledWavelengths lambda = SampledWavelengths::sample_visible(sample.wavelength_u);
    const std::optional<CameraRay> r = camera.generate_ray(shifted, lambda);
    if (!r) continue;
    return Ray{ray.o + (r->ray.o - ray.o) * (scale / step), ray.d + (r->ray.d - ray.d) * (scale / step)};
  }
  return std::nullopt;
}

// Where `r` meets the plane through p with normal n, minus p; zero for a ray parallel to the
// plane (no meeting point) or a non-finite result.
Vec3 tangent_plane_offset(const Ray& r, const Vec3& p, const Vec3& n) {
  const float denom = dot(n, r.d);
  if (denom == 0.f) return Vec3(0.f);
  const float t = dot(n, p - r.o) / denom;
  const Vec3 offset = r.o + t * r.d - p;
  return std::isfinite(offset.x + offset.y + offset.z) ? offset : Vec3(0.f);
}
}  // namespace

void set_position_differentials(const Camera& camera, const CameraSample& sample, const Ray& ray, int spp,
                                VisibleSurface& vs) {
  CameraSample plain = sample;
  plain.filter = nullptr;  // the hero wavelength's ray alone, never a splat
  plain.splat = false;
  const float scale = std::max(0.125f, 1.f / std::sqrt(float(std::max(spp, 1))));
  Vec3* dp[2] = {&vs.dpdx, &vs.dpdy};
  for (int axis = 0; axis < 2; ++axis) {
    const std::optional<Ray> r = differential_ray(camera, plain, ray, axis, scale);
    *dp[axis] = r ? tangent_plane_offset(*r, vs.p, vs.n) : Vec3(0.f);
  }
}

const std::vector<std::string>& GBuffer::channel_names() {
  static const std::vector<std::string> names = {"Albedo.R",
                                                 "Albedo.G",
                                                 "Albedo.B",
                                                 "P.X",
                                                 "P.Y",
                                                 "P.Z",
                                                 "dzdx",
                                                 "dzdy",
                                                 "N.X",
                                                 "N.Y",
                                                 "N.Z",
                                                 "Ns.X",
                                                 "Ns.Y",
                                                 "Ns.Z",
                                                 "u",
                                                 "v",
                                                 "Variance.R",
                                                 "Variance.G",
                                                 "Variance.B",
                                                 "RelativeVariance.R",
                                                 "RelativeVariance.G",
                                                 "RelativeVariance.B"};
  return names;
}

GBuffer::GBuffer(size_t pixels, const AnimatedTransform& world_from_output)
    : sums_(pixels * kAccumulators, 0.0),
      world_from_output_(world_from_output),
      output_from_world_(world_from_output.start().inverse()) {}

void GBuffer::add(size_t pixel, const VisibleSurface& vs, const SampledWavelengths& lambda, const RGB& rgb, float w) {
  if (!vs.set) return;
  double* s = &sums_[pixel * kAccumulators];
  const Transform output_from_world =
      world_from_output_.is_animated() ? world_from_output_.interpolate(vs.time).inverse() : output_from_world_;
  const Vec3 p = output_from_world.point(vs.p);
  const Vec3 n = output_from_world.normal(vs.n), ns = output_from_world.normal(vs.ns);
  // The albedo as a reflectance under the colour space's white (white_illuminant: luminance 1),
  // so that albedo 1 is (1, 1, 1).
  SampledSpectrum lit = vs.albedo;
  for (int i = 0; i < kSpectrumSamples; ++i) lit[i] *= white_illuminant(lambda[i]);
  const RGB albedo = sampled_to_rgb(lit, lambda);
  for (int c = 0; c < 3; ++c) {
    s[kP + c] += double(w) * p[c];
    s[kN + c] += double(w) * n[c];
    s[kNs + c] += double(w) * ns[c];
    s[kAlbedo + c] += double(w) * albedo[c];
  }
  s[kUv] += double(w) * vs.uv.x;
  s[kUv + 1] += double(w) * vs.uv.y;
  s[kDz] += double(w) * output_from_world.vector(vs.dpdx).z;
  s[kDz + 1] += double(w) * output_from_world.vector(vs.dpdy).z;
  s[kWeight] += w;
  // Welford's update of the mean and the sum of squared deviations.
  const double count = (s[kCount] += 1.0);
  for (int c = 0; c < 3; ++c) {
    const double d = double(rgb[c]) - s[kMean + c];
    s[kMean + c] += d / count;
    s[kM2 + c] += d * (double(rgb[c]) - s[kMean + c]);
  }
}

void GBuffer::channels(size_t pixel, double film_weight, float scale, float* out) const {
  const double* s = &sums_[pixel * kAccumulators];
  auto finite = [](double v) { return std::isfinite(v) ? float(v) : 0.f; };
  for (int c = 0; c < 3; ++c) out[c] = film_weight > 0 ? finite(s[kAlbedo + c] / film_weight) : 0.f;
  const double w = s[kWeight];
  for (int c = 0; c < 3; ++c) out[3 + c] = w > 0 ? finite(s[kP + c] / w) : 0.f;
  for (int k = 0; k < 2; ++k) out[6 + k] = w > 0 ? finite(std::abs(s[kDz + k]) / w) : 0.f;  // pbrt-v4's |mean|
  for (int k = 0; k < 2; ++k) {  // N, then Ns: the sum's direction, 0 when it has none
    const double* v = &s[k == 0 ? kN : kNs];
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; ++c) out[8 + 3 * k + c] = len > 0 ? finite(v[c] / len) : 0.f;
  }
  for (int k = 0; k < 2; ++k) out[14 + k] = w > 0 ? finite(s[kUv + k] / w) : 0.f;
  const double count = s[kCount];
  for (int c = 0; c < 3; ++c) {
    // In the image's units: colours times the film's scale.
    const double mean = double(scale) * s[kMean + c];
    const double var = count > 1 ? double(scale) * double(scale) * s[kM2 + c] / (count - 1) : 0.0;
    out[16 + c] = finite(var);
    out[19 + c] = (count < 1 || mean == 0) ? 0.f : finite(var / mean);
  }
}

}  // namespace eyetrace
