#include "lights/environment_map.h"

namespace eyetrace {

EnvironmentMap::EnvironmentMap(RGBImage image, SphereMapping mapping) : image_(std::move(image)), mapping_(mapping) {
  // Density over the square proportional to luminance times the pixel's solid angle, so
  // that the density per solid angle follows luminance (exactly for equal-area pixels; to
  // within the variation of sin(theta) across a lat-long row).
  std::vector<float> f(image_.pixels.size());
  for (int y = 0; y < image_.height; ++y) {
    float omega = pixel_solid_angle(y);
    for (int x = 0; x < image_.width; ++x) f[size_t(y) * image_.width + x] = luminance(image_.at(x, y)) * omega;
  }
  distribution_ = PiecewiseConstant2D(f, image_.width, image_.height);
}

Vec2 EnvironmentMap::to_square(const Vec3& w) const {
  return mapping_ == SphereMapping::EqualArea ? equal_area_sphere_to_square(w) : latlong_sphere_to_square(w);
}

Vec3 EnvironmentMap::to_sphere(Vec2 uv) const {
  return mapping_ == SphereMapping::EqualArea ? equal_area_square_to_sphere(uv) : latlong_square_to_sphere(uv);
}

float EnvironmentMap::sphere_per_square(const Vec3& w) const {
  if (mapping_ == SphereMapping::EqualArea) return 4.f * kPi;
  return 2.f * kPi * kPi * safe_sqrt(1.f - w.z * w.z);
}

float EnvironmentMap::pixel_solid_angle(int y) const {
  float n = float(image_.width) * float(image_.height);
  if (mapping_ == SphereMapping::EqualArea) return 4.f * kPi / n;
  float theta0 = kPi * float(y) / float(image_.height), theta1 = kPi * float(y + 1) / float(image_.height);
  return (2.f * kPi / float(image_.width)) * (std::cos(theta0) - std::cos(theta1));
}

RGB EnvironmentMap::radiance(const Vec3& w) const { return image_.nearest(to_square(w)); }

std::optional<Vec3> EnvironmentMap::sample(Vec2 u, float* pdf_out) const {
  float map_pdf = 0.f;
  Vec2 uv = distribution_.sample(u, &map_pdf);
  if (!(map_pdf > 0.f)) return std::nullopt;
  Vec3 w = glm::normalize(to_sphere(uv));
  // The density is re-derived from w so that pdf() of the returned direction is identical,
  // even when rounding moves a point on a pixel edge into its neighbour.
  float p = pdf(w);
  if (!(p > 0.f) || !std::isfinite(p)) return std::nullopt;
  *pdf_out = p;
  return w;
}

float EnvironmentMap::pdf(const Vec3& w) const {
  float jac = sphere_per_square(w);
  if (!(jac > 0.f)) return 0.f;  // the poles of a lat-long map have no area
  Vec2 uv = glm::min(to_square(w), Vec2(kOneMinusEpsilon));
  float p = distribution_.pdf(uv) / jac;
  return std::isfinite(p) ? p : 0.f;
}

RGB EnvironmentMap::mean_radiance() const {
  RGB sum(0.f);
  for (int y = 0; y < image_.height; ++y) {
    RGB row(0.f);
    for (int x = 0; x < image_.width; ++x) row += image_.at(x, y);
    sum += row * pixel_solid_angle(y);
  }
  return sum / (4.f * kPi);
}

// Equal-area: midpoint rule over pixels (every pixel the same solid angle), except that
// pixels near the horizon, where cos+ has its kink, are subdivided 8 x 8 (the midpoint rule
// is biased low there). Lat-long: each row exactly, since cos(theta) sin(theta) integrates
// to (sin^2 theta1 - sin^2 theta0) / 2.
float EnvironmentMap::up_illuminance() const {
  double E = 0.0;
  for (int y = 0; y < image_.height; ++y) {
    if (mapping_ == SphereMapping::LatLong) {
      float theta0 = kPi * float(y) / float(image_.height);
      float theta1 = std::min(kPi * float(y + 1) / float(image_.height), kPi / 2.f);
      if (theta0 >= kPi / 2.f) break;
      float row_weight = (2.f * kPi / float(image_.width)) * 0.5f * (sqr(std::sin(theta1)) - sqr(std::sin(theta0)));
      for (int x = 0; x < image_.width; ++x) E += double(luminance(image_.at(x, y))) * row_weight;
      continue;
    }
    for (int x = 0; x < image_.width; ++x) E += double(luminance(image_.at(x, y))) * equal_area_pixel_cosine(x, y);
  }
  return float(E);
}

// Integral of max(0, z) over pixel (x, y) of the equal-area map.
float EnvironmentMap::equal_area_pixel_cosine(int x, int y) const {
  float w = float(image_.width), h = float(image_.height);
  float omega = 4.f * kPi / (w * h);
  float zc = equal_area_square_to_sphere(Vec2((float(x) + 0.5f) / w, (float(y) + 0.5f) / h)).z;
  // Across one pixel z changes by at most about 4 pixel widths of the [-1, 1] square.
  if (std::abs(zc) > 8.f / std::min(w, h)) return std::max(0.f, zc) * omega;
  const int n = 8;
  float sum = 0.f;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Vec2 uv((float(x) + (float(i) + 0.5f) / n) / w, (float(y) + (float(j) + 0.5f) / n) / h);
      sum += std::max(0.f, equal_area_square_to_sphere(uv).z);
    }
  return sum / float(n * n) * omega;
}

}  // namespace eyetrace
