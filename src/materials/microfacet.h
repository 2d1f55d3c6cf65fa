// Trowbridge-Reitz (GGX) microfacet distribution with Smith masking and sampling of the
// visible normals (Heitz 2018), as in pbrt-v4. Local frame: +z is the macro normal.
#pragma once
#include "core/math.h"
#include "core/sampling.h"

namespace eyetrace {

class TrowbridgeReitz {
 public:
  TrowbridgeReitz() = default;
  TrowbridgeReitz(float alpha_x, float alpha_y) : ax_(alpha_x), ay_(alpha_y) {
    // Below this the distribution is numerically a delta: treat as a smooth surface
    // rather than risk overflow in D().
    if (!effectively_smooth()) {
      ax_ = std::max(ax_, 1e-4f);
      ay_ = std::max(ay_, 1e-4f);
    }
  }
  // pbrt-v4's remapping: a perceptually even roughness in [0, 1] to alpha.
  static float roughness_to_alpha(float roughness) { return std::sqrt(std::max(0.f, roughness)); }

  bool effectively_smooth() const { return std::max(ax_, ay_) < 1e-3f; }
  float alpha_x() const { return ax_; }
  float alpha_y() const { return ay_; }

  float D(const Vec3& wm) const {
    float cos2 = wm.z * wm.z;
    float sin2 = std::max(0.f, 1.f - cos2);
    if (cos2 <= 0.f) return 0.f;
    float tan2 = sin2 / cos2;
    float cos2_phi = sin2 > 0.f ? wm.x * wm.x / sin2 : 1.f;
    float sin2_phi = sin2 > 0.f ? wm.y * wm.y / sin2 : 0.f;
    float e = tan2 * (cos2_phi / (ax_ * ax_) + sin2_phi / (ay_ * ay_));
    return 1.f / (kPi * ax_ * ay_ * cos2 * cos2 * sqr(1.f + e));
  }
  float lambda(const Vec3& w) const {
    float cos2 = w.z * w.z;
    float sin2 = std::max(0.f, 1.f - cos2);
    if (cos2 <= 0.f) return kInfinity;
    float tan2 = sin2 / cos2;
    float alpha2 = sin2 > 0.f ? (w.x * w.x * ax_ * ax_ + w.y * w.y * ay_ * ay_) / sin2 : ax_ * ay_;
    return (std::sqrt(1.f + alpha2 * tan2) - 1.f) * 0.5f;
  }
  float G1(const Vec3& w) const { return 1.f / (1.f + lambda(w)); }
  // Height-correlated masking-shadowing.
  float G(const Vec3& wo, const Vec3& wi) const { return 1.f / (1.f + lambda(wo) + lambda(wi)); }
  // Distribution of normals visible from w.
  float D(const Vec3& w, const Vec3& wm) const {
    if (w.z == 0.f) return 0.f;
    return G1(w) / std::abs(w.z) * D(wm) * std::abs(glm::dot(w, wm));
  }
  float pdf(const Vec3& w, const Vec3& wm) const { return D(w, wm); }

  Vec3 sample_wm(const Vec3& w, Vec2 u) const {
    // Stretch to the hemisphere configuration, sample the projected visible disk, unstretch.
    Vec3 wh = glm::normalize(Vec3(ax_ * w.x, ay_ * w.y, w.z));
    if (wh.z < 0.f) wh = -wh;
    Vec3 t1 = wh.z < 0.99999f ? glm::normalize(glm::cross(Vec3(0.f, 0.f, 1.f), wh)) : Vec3(1.f, 0.f, 0.f);
    Vec3 t2 = glm::cross(wh, t1);
    Vec2 p = sample_uniform_disk_polar(u);
    float h = std::sqrt(std::max(0.f, 1.f - p.x * p.x));
    float s = (1.f + wh.z) * 0.5f;
    p.y = (1.f - s) * h + s * p.y;
    float pz = std::sqrt(std::max(0.f, 1.f - p.x * p.x - p.y * p.y));
    Vec3 nh = p.x * t1 + p.y * t2 + pz * wh;
    return glm::normalize(Vec3(ax_ * nh.x, ay_ * nh.y, std::max(1e-6f, nh.z)));
  }

 private:
  float ax_ = 0.f, ay_ = 0.f;
};

}  // namespace eyetrace
