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

std::optional<Spectrum> emission_param_or_null(const PluginParams& params, const std::string& name) {
  if (!params.has(name)) return std::nullopt;
  const SpectrumValue v = params.get_spectrum(name, SpectrumType::Illuminant);
  if (v.rgb && (v.rgb->r < 0.f || v.rgb->g < 0.f || v.rgb->b < 0.f))
    params.fail(name, fmt::format("emission ({}, {}, {}) has a negative component", v.rgb->r, v.rgb->g, v.rgb->b));
  if (!v.rgb)
    for (float l = kLambdaMin; l <= kLambdaMax; l += 1.f)
      if (v.spectrum(l) < 0.f) params.fail(name, fmt::format("emission is negative at {} nm", l));
  return v.as(SpectrumType::Illuminant);
}

Spectrum emission_param(const PluginParams& params, const std::string& name) {
  const std::optional<Spectrum> given = emission_param_or_null(params, name);
  return given ? *given : params.get_spectrum(name, SpectrumType::Illuminant).as(SpectrumType::Illuminant);
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
