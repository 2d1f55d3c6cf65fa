// The Henyey-Greenstein phase function, the density of scattering directions in a medium:
// p(theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)), theta measured from the
// direction the light was travelling (g > 0 scatters forwards; its mean cosine is g). It is
// normalised over the sphere and sampled exactly, so a sample's weight p / pdf is 1.
#pragma once
#include <cmath>

#include "core/constants.h"
#include "core/math.h"
#include "core/sampling.h"

namespace eyetrace {

// cos_theta: between the incoming travel direction and the scattered one.
inline float henyey_greenstein(float cos_theta, float g) {
  float denom = 1.f + g * g - 2.f * g * cos_theta;
  return (1.f - g * g) / (4.f * kPi * denom * std::sqrt(std::max(denom, 1e-20f)));
}

// A direction scattered from travel direction `d` (unit) by inverting the CDF of cos theta;
// the density is henyey_greenstein(dot(d, result), g).
inline Vec3 sample_henyey_greenstein(const Vec3& d, float g, Vec2 u) {
  float cos_theta;
  if (std::abs(g) < 1e-3f) {
    cos_theta = 1.f - 2.f * u.x;  // isotropic (the formula below divides by g)
  } else {
    float s = (1.f - g * g) / (1.f - g + 2.f * g * u.x);
    cos_theta = (1.f + g * g - s * s) / (2.f * g);
  }
  cos_theta = std::clamp(cos_theta, -1.f, 1.f);
  float sin_theta = std::sqrt(std::max(0.f, 1.f - cos_theta * cos_theta));
  float phi = 2.f * kPi * u.y;
  Vec3 t, b;
  coordinate_system(d, &t, &b);
  return glm::normalize(sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + cos_theta * d);
}

}  // namespace eyetrace
