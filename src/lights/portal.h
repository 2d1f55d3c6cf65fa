// An infinite light's portal (pbrt-v4's "portal" on an "infinite" light): a rectangle, four
// world-space corners in order, through which alone the environment reaches the scene, as
// a window does an interior's. pbrt-v4's rules: the portal's frame has x along corner 0 -> 3,
// y along 0 -> 1 and z = x cross y, pointing out of the scene; a ray sees the environment only
// if it leaves the scene through the rectangle (it starts behind the portal's plane, on the
// -z side, and meets the plane inside the rectangle); elsewhere the light is black.
//
// Sampling: pbrt-v4 samples the environment re-mapped to the portal's directions by
// luminance. eyetrace samples a point of the rectangle uniformly by area (the density is
// then dist^2 / (A cos) in solid angle), and an image light mixes that half and half with its
// own luminance sampling restricted to the portal, so that a sun seen through the window is
// found too.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"

namespace eyetrace {

class Portal {
 public:
  // The portal through `corners`, or nullopt with *error saying why not (not 4 points, not a
  // rectangle: pbrt-v4's tolerance of 0.001 on the cosines between its sides).
  static std::optional<Portal> make(const std::vector<Vec3>& corners, std::string* error);

  // Whether the ray from o along d (any length) leaves through the portal.
  bool passes(const Vec3& o, const Vec3& d) const;
  // A unit direction from p towards a uniformly chosen point of the rectangle, and its
  // solid-angle density; nullopt from a point not behind the portal.
  std::optional<std::pair<Vec3, float>> sample(const Vec3& p, Vec2 u) const;
  // The density sample() has for the unit direction d from p (0 where d misses the portal).
  float pdf(const Vec3& p, const Vec3& d) const;
  float area() const { return len_x_ * len_y_; }

 private:
  // Distance along the unit direction d from o to the portal, if it leaves through it.
  std::optional<float> exit_distance(const Vec3& o, const Vec3& d) const;
  Vec3 p0_{0.f}, x_{1.f, 0.f, 0.f}, y_{0.f, 1.f, 0.f}, z_{0.f, 0.f, 1.f};
  float len_x_ = 0.f, len_y_ = 0.f;
};

}  // namespace eyetrace
