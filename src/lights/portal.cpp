#include "lights/portal.h"

#include <cmath>

#include <fmt/format.h>

namespace eyetrace {

std::optional<Portal> Portal::make(const std::vector<Vec3>& c, std::string* error) {
  if (c.size() != 4) {
    *error = fmt::format("a portal has 4 corners, not {}", c.size());
    return std::nullopt;
  }
  const Vec3 e03 = c[3] - c[0], e01 = c[1] - c[0];
  Portal p;
  p.p0_ = c[0];
  p.len_x_ = glm::length(e03);
  p.len_y_ = glm::length(e01);
  if (!(p.len_x_ > 0.f) || !(p.len_y_ > 0.f) || !std::isfinite(p.len_x_ * p.len_y_)) {
    *error = "a portal's sides must have positive, finite lengths";
    return std::nullopt;
  }
  p.x_ = e03 / p.len_x_;
  p.y_ = e01 / p.len_y_;
  // pbrt-v4's check: opposite sides parallel and adjacent sides perpendicular, to 0.001.
  const Vec3 e12 = glm::normalize(c[2] - c[1]), e32 = glm::normalize(c[2] - c[3]);
  if (std::abs(glm::dot(p.y_, e32) - 1.f) > 1e-3f || std::abs(glm::dot(e12, p.x_) - 1.f) > 1e-3f ||
      std::abs(glm::dot(p.y_, e12)) > 1e-3f || std::abs(glm::dot(e12, e32)) > 1e-3f ||
      std::abs(glm::dot(e32, p.x_)) > 1e-3f || std::abs(glm::dot(p.x_, p.y_)) > 1e-3f) {
    *error = "the portal's corners are not a rectangle (in order, corner 0 -> 1 -> 2 -> 3)";
    return std::nullopt;
  }
  p.z_ = glm::normalize(glm::cross(p.x_, p.y_));
  return p;
}

std::optional<float> Portal::exit_distance(const Vec3& o, const Vec3& d) const {
  // Leaving means going out along +z from behind the plane; a ray parallel to the plane
  // (cos 0) or coming back in never leaves through it.
  const float cos = glm::dot(d, z_);
  const float depth = glm::dot(p0_ - o, z_);  // > 0: o is behind the plane
  if (!(cos > 0.f) || !(depth > 0.f)) return std::nullopt;
  const float t = depth / cos;
  const Vec3 q = o + t * d - p0_;
  const float s = glm::dot(q, x_), r = glm::dot(q, y_);
  if (!(s >= 0.f && s <= len_x_ && r >= 0.f && r <= len_y_) || !std::isfinite(t)) return std::nullopt;
  return t;
}

bool Portal::passes(const Vec3& o, const Vec3& d) const {
  const float len = glm::length(d);
  return len > 0.f && exit_distance(o, d / len).has_value();
}

std::optional<std::pair<Vec3, float>> Portal::sample(const Vec3& p, Vec2 u) const {
  const Vec3 q = p0_ + (u.x * len_x_) * x_ + (u.y * len_y_) * y_;
  const Vec3 w = q - p;
  const float dist2 = glm::dot(w, w);
  if (!(dist2 > 0.f)) return std::nullopt;
  const Vec3 d = w / std::sqrt(dist2);
  const float cos = glm::dot(d, z_);
  if (!(cos > 0.f) || !(glm::dot(p0_ - p, z_) > 0.f)) return std::nullopt;
  const float pdf = dist2 / (area() * cos);
  if (!std::isfinite(pdf)) return std::nullopt;
  return std::pair{d, pdf};
}

float Portal::pdf(const Vec3& p, const Vec3& d) const {
  const std::optional<float> t = exit_distance(p, d);
  if (!t) return 0.f;
  const float pdf = *t * *t / (area() * glm::dot(d, z_));
  return std::isfinite(pdf) ? pdf : 0.f;
}

}  // namespace eyetrace
