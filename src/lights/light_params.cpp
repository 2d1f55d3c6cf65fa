#include "lights/light_params.h"

#include <limits>

namespace eyetrace {

std::optional<RGB> emission_param_or_null(const ParameterList& params, const std::string& name) {
  std::optional<RGB> c = params.get_rgb(name);
  if (c && (c->r < 0.f || c->g < 0.f || c->b < 0.f))
    params.fail(name, fmt::format("emission ({}, {}, {}) has a negative component", c->r, c->g, c->b));
  return c;
}

RGB emission_param(const ParameterList& params, const std::string& name) {
  return emission_param_or_null(params, name).value_or(RGB(1.f));
}

float scale_param(const ParameterList& params) {
  return params.get_float_in("scale", 1.f, 0.f, std::numeric_limits<float>::max());
}

std::optional<float> positive_param(const ParameterList& params, const std::string& name) {
  if (!params.has(name)) {
    params.get_float(name, 0.f);  // records the query, for "did you mean" hints
    return std::nullopt;
  }
  float v = params.get_float(name, 0.f);
  if (!(v > 0.f)) params.fail(name, fmt::format("value {} must be positive", v));
  return v;
}

float photometric_factor(std::optional<float> target, float emitted_luminance) {
  if (!target || !(emitted_luminance > 0.f)) return 1.f;
  float f = *target / emitted_luminance;
  return std::isfinite(f) ? f : 1.f;
}

}  // namespace eyetrace
