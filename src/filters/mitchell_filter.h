// The Mitchell-Netravali cubic filter (SIGGRAPH 1988; pbrt-v4's MitchellFilter), separable, with
// the family's B and C parameters. Its negative lobes sharpen edges; it is importance-sampled
// through a table of |f| and carries the sign in the sample weight.
#pragma once
#include <memory>

#include "core/filter.h"
#include "filters/filter_sampler.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class MitchellFilter : public Filter {
 public:
  MitchellFilter(Vec2 radius, float b, float c);
  Vec2 radius() const override { return radius_; }
  float evaluate(Vec2 p) const override {
    return mitchell_1d(2.f * p.x / radius_.x) * mitchell_1d(2.f * p.y / radius_.y);
  }
  FilterSample sample(Vec2 u) const override { return sampler_.sample(*this, u); }
  std::string to_string() const override;
  // The cubic integrates to 1 over [-2, 2] for every B and C, so f integrates to rx ry / 4.
  float integral() const override { return radius_.x * radius_.y / 4.f; }

  // The 1D kernel on [-2, 2] (zero outside).
  float mitchell_1d(float x) const;

 private:
  Vec2 radius_;
  float b_, c_;
  filter_sampling::FilterSampler sampler_;
};

// pbrt-v4 "mitchell": float xradius, yradius (2), B, C (1/3).
const PluginSpec& mitchell_filter_spec();
std::unique_ptr<Filter> create_mitchell_filter(const ParameterList& params);

}  // namespace eyetrace
