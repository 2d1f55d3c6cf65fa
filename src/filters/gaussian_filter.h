// The Gaussian filter, shifted down so that it reaches zero at the radius (pbrt-v4's
// GaussianFilter): f(x, y) = g(x) g(y), g(x) = max(0, G(x) - G(r)), G the normal density with
// standard deviation sigma. Importance-sampled through a tabulated distribution.
#pragma once
#include <memory>

#include "core/filter.h"
#include "filters/axis_factor_table.h"
#include "filters/filter_sampler.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class GaussianFilter : public Filter {
 public:
  GaussianFilter(Vec2 radius, float sigma);
  Vec2 radius() const override { return radius_; }
  float evaluate(Vec2 p) const override;
  float evaluate_axis(float t, int axis) const override { return float(shifted_gaussian(t, axis)); }
  void evaluate_axis_row(double t0, int n, int axis, float* out) const override;
  FilterSample sample(Vec2 u) const override { return sampler_.sample(*this, u); }
  std::string to_string() const override;
  float integral() const override { return integral_; }

  // The smallest sigma whose shape the sampling table resolves, for a given radius.
  static float min_sigma(Vec2 radius);

 private:
  // g(x) for |x| < r, 0 beyond, r the radius along `axis`.
  double shifted_gaussian(double x, int axis) const;

  Vec2 radius_;
  float sigma_;
  float integral_;
  // Constants of shifted_gaussian, set before the sampler tabulates evaluate(): 1 / sqrt(pi s2)
  // and G(r) / norm = exp(-r^2 / s2) per axis (s2 = 2 sigma^2).
  double norm_, edge_[2];
  AxisFactorTable rows_[2];  // g per axis, for evaluate_axis_row
  filter_sampling::FilterSampler sampler_;
};

// pbrt-v4 "gaussian": float xradius, yradius (1.5), sigma (0.5).
const PluginSpec& gaussian_filter_spec();
std::unique_ptr<Filter> create_gaussian_filter(const ParameterList& params);

}  // namespace eyetrace
