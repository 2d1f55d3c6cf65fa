#include "lights/light_params.h"

#include <limits>

namespace eyetrace {

ParamSpec emission_param_spec(const std::string& name, const std::string& doc) {
  return param::spectrum(name, 1).describe(doc);
}

ParamSpec scale_param_spec() { return param::real("scale", 1).at_least(0).describe("multiplies the emission"); }

ParamSpec photometric_param_spec(const std::string& name, const std::string& doc) {
  return param::real(name).above(0).describe(doc);
}

std::optional<RGB> emission_param_or_null(const PluginParams& params, const std::string& name) {
  if (!params.has(name)) return std::nullopt;
  const RGB c = params.get_rgb(name);
  if (c.r < 0.f || c.g < 0.f || c.b < 0.f)
    params.fail(name, fmt::format("emission ({}, {}, {}) has a negative component", c.r, c.g, c.b));
  return c;
}

RGB emission_param(const PluginParams& params, const std::string& name) {
  const std::optional<RGB> given = emission_param_or_null(params, name);
  return given ? *given : params.get_rgb(name);  // absent: the declared default
}

float scale_param(const PluginParams& params) { return params.get_float("scale"); }

std::optional<float> photometric_param(const PluginParams& params, const std::string& name) {
  if (!params.has(name)) return std::nullopt;
  return params.get_float(name);
}

float photometric_factor(std::optional<float> target, float emitted_luminance) {
  if (!target || !(emitted_luminance > 0.f)) return 1.f;
  float f = *target / emitted_luminance;
  return std::isfinite(f) ? f : 1.f;
}

}  // namespace eyetrace
