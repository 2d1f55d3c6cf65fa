// The box filter: every sample within the radius counts equally (pbrt-v4's BoxFilter). Sampled
// exactly, so every weight is 1.
#pragma once
#include <memory>

#include "core/filter.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class BoxFilter : public Filter {
 public:
  explicit BoxFilter(Vec2 radius) : radius_(radius) {}
  Vec2 radius() const override { return radius_; }
  float evaluate(Vec2 p) const override { return std::abs(p.x) <= radius_.x && std::abs(p.y) <= radius_.y ? 1.f : 0.f; }
  FilterSample sample(Vec2 u) const override;
  bool constant() const override { return true; }
  std::string to_string() const override;
  float integral() const override { return 4.f * radius_.x * radius_.y; }

 private:
  Vec2 radius_;
};

// pbrt-v4 "box": float xradius, yradius (0.5).
const PluginSpec& box_filter_spec();
std::unique_ptr<Filter> create_box_filter(const ParameterList& params);

}  // namespace eyetrace
