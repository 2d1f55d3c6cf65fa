// The triangle (tent) filter: weight falling linearly to zero at the radius (pbrt-v4's
// TriangleFilter). Each axis is sampled exactly by inverting the tent's CDF, so weights are 1.
#pragma once
#include <memory>

#include "core/filter.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class TriangleFilter : public Filter {
 public:
  explicit TriangleFilter(Vec2 radius) : radius_(radius) {}
  Vec2 radius() const override { return radius_; }
  float evaluate(Vec2 p) const override {
    return std::max(0.f, radius_.x - std::abs(p.x)) * std::max(0.f, radius_.y - std::abs(p.y));
  }
  FilterSample sample(Vec2 u) const override;
  std::string to_string() const override;
  float integral() const override { return sqr(radius_.x) * sqr(radius_.y); }

 private:
  Vec2 radius_;
};

// A sample of the density (r - |x|) / r^2 on [-r, r] from u in [0, 1).
float sample_tent(float u, float r);

// pbrt-v4 "triangle": float xradius, yradius (2).
const PluginSpec& triangle_filter_spec();
std::unique_ptr<Filter> create_triangle_filter(const ParameterList& params);

}  // namespace eyetrace
