// The windowed sinc filter (pbrt-v4's LanczosSincFilter, "sinc"): f(x, y) = w(x, rx) w(y, ry),
// w(x, r) = sinc(x) sinc(x / tau) for |x| <= r and 0 beyond, sinc(x) = sin(pi x) / (pi x). Its
// negative lobes sharpen edges (and ring). Sampled as pbrt-v4 samples it: |f| is tabulated on a
// grid (32 cells per pixel of radius) and drawn from, and each sample carries the sign of f in
// its weight (filters/filter_sampler.h: weight f(p) / (pdf(p) * integral of f), mean 1).
#pragma once
#include <memory>

#include "core/filter.h"
#include "filters/filter_sampler.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class SincFilter : public Filter {
 public:
  SincFilter(Vec2 radius, float tau);
  Vec2 radius() const override { return radius_; }
  float evaluate(Vec2 p) const override {
    return float(windowed_sinc(p.x, radius_.x, tau_) * windowed_sinc(p.y, radius_.y, tau_));
  }
  FilterSample sample(Vec2 u) const override { return sampler_.sample(*this, u); }
  std::string to_string() const override;
  // The signed integral of f over its support (separable: the product of the two axes').
  float integral() const override { return integral_; }

  // sin(pi x) / (pi x), 1 at 0.
  static double sinc(double x);
  // sinc(x) sinc(x / tau) within the radius, 0 beyond (pbrt-v4's WindowedSinc).
  static double windowed_sinc(double x, double radius, double tau);
  // The integral of windowed_sinc over [-radius, radius] (composite Simpson, 2048 intervals per
  // pixel of radius: the integrand is smooth inside, so the error is below 1e-12).
  static double windowed_sinc_integral(double radius, double tau);

 private:
  Vec2 radius_;
  float tau_;
  float integral_;
  filter_sampling::FilterSampler sampler_;
};

// pbrt-v4 "sinc": float xradius, yradius (4), tau (3).
const PluginSpec& sinc_filter_spec();
std::unique_ptr<Filter> create_sinc_filter(const ParameterList& params);

}  // namespace eyetrace
