// Spectrum-valued scene parameters, checked and kept as given (scene/spectrum_param.h).
#include "scene/spectrum_param.h"

#include <algorithm>
#include <vector>

#include "core/spectrum.h"

namespace eyetrace {

namespace {

struct Pairs {
  std::vector<float> lambda, value;
};

// Spectrum files were read by the parser (scene/spectrum_file.h); one that was not there is
// left as its path, and reported here, where a plugin reads it.
[[noreturn]] void unknown_name(const Param& p, const std::string& name) {
  if (name.find('.') != std::string::npos || name.find('/') != std::string::npos)
    throw_missing_file(p.loc, p.name, fmt::format("parameter \"{}\": spectrum file \"{}\" not found", p.name, name));
  std::vector<std::string> names = named_spectrum_names();
  std::string list, hint = closest_match(name, names);
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  fail(p.loc, "parameter \"{}\": unknown named spectrum \"{}\"{}; known spectra: {}", p.name, name,
       hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint), list);
}

const NamedSpectrum& named_of(const Param& p) {
  if (p.strings.size() != 1) fail(p.loc, "parameter \"{}\" takes one spectrum name", p.name);
  const NamedSpectrum* n = find_named_spectrum(p.strings[0]);
  if (!n) unknown_name(p, p.strings[0]);
  return *n;
}

// [lambda value ...] pairs, checked: increasing positive wavelengths.
Pairs pairs_of(const Param& p) {
  const auto& v = p.numbers;
  if (v.size() < 2 || v.size() % 2 != 0)
    fail(p.loc, "parameter \"{}\": a spectrum is one value or (wavelength, value) pairs; got {} values", p.name,
         v.size());
  std::vector<float> lambda, value;
  for (size_t i = 0; i < v.size(); i += 2) {
    if (v[i] <= 0.0 || (!lambda.empty() && float(v[i]) <= lambda.back()))
      fail(p.loc, "parameter \"{}\": wavelengths must be positive and increasing (got {} nm)", p.name, v[i]);
    lambda.push_back(float(v[i]));
    value.push_back(float(v[i + 1]));
  }
  return {lambda, value};
}

}  // namespace

SpectrumValue spectrum_param_value(const Param& p, SpectrumType type) {
  std::string t = p.canonical_type();
  if (t == "rgb") {
    if (p.numbers.size() != 3) fail(p.loc, "parameter \"{}\" takes 3 values, got {}", p.name, p.numbers.size());
    return {RGB(float(p.numbers[0]), float(p.numbers[1]), float(p.numbers[2])), {}};
  }
  if (t == "blackbody") {
    if (p.numbers.size() != 1) fail(p.loc, "parameter \"{}\": blackbody takes one temperature in kelvin", p.name);
    // Below 100 K the visible tail spans more than float range; such a body is black anyway.
    if (!(p.numbers[0] >= 100.0 && p.numbers[0] <= 1e7))
      fail(p.loc, "parameter \"{}\": blackbody temperature {} K is outside [100, 1e7] K", p.name, p.numbers[0]);
    return {std::nullopt, Spectrum::blackbody(float(p.numbers[0]))};
  }
  if (t != "spectrum") fail(p.loc, "parameter \"{}\" of type \"{}\" is not a spectrum", p.name, p.type);
  if (!p.strings.empty()) return {std::nullopt, Spectrum::named(named_of(p), type)};
  if (p.numbers.size() == 1) return {RGB(float(p.numbers[0])), {}};
  Pairs pairs = pairs_of(p);
  return {std::nullopt, Spectrum::tabulated(std::move(pairs.lambda), std::move(pairs.value), type)};
}

void warn_if_not_reflectance(const Param& p, const RGB& rgb) {
  const RGB clamped = glm::clamp(rgb, RGB(0.f), RGB(1.f));
  if (clamped == rgb) return;
  const char* why = "is read as a reflectance, which lies in [0, 1]";
  if (p.canonical_type() == "spectrum")  // a constant spectrum c, kept as RGB (c, c, c)
    warn(p.loc,
         fmt::format("parameter \"{}\": the constant spectrum {} {}; clamped to {}", p.name, rgb.r, why, clamped.r));
  else
    warn(p.loc, fmt::format("parameter \"{}\": RGB ({}, {}, {}) {}; clamped to ({}, {}, {})", p.name, rgb.r, rgb.g,
                            rgb.b, why, clamped.r, clamped.g, clamped.b));
}

float spectrum_param_at(const Param& p, float lambda_nm) {
  std::string type = p.canonical_type();
  if (type == "float") {
    if (p.numbers.size() != 1) fail(p.loc, "parameter \"{}\" takes one value, got {}", p.name, p.numbers.size());
    return float(p.numbers[0]);
  }
  if (type == "rgb") {
    if (p.numbers.size() != 3) fail(p.loc, "parameter \"{}\" takes 3 values, got {}", p.name, p.numbers.size());
    return float(p.numbers[1]);
  }
  if (type != "spectrum")
    fail(p.loc, "parameter \"{}\" has type \"{}\" but must be \"float\" or \"spectrum\"", p.name, p.type);
  if (!p.strings.empty()) return evaluate_named_spectrum(named_of(p), lambda_nm);
  if (p.numbers.size() == 1) return float(p.numbers[0]);
  Pairs pairs = pairs_of(p);
  return interpolate_spectrum(pairs.lambda, pairs.value, lambda_nm);
}

namespace {

// Smallest value over the sampled range (RGB: smallest channel).
float min_value(const SpectrumValue& v) {
  if (v.rgb) return std::min({v.rgb->r, v.rgb->g, v.rgb->b});
  float lo = v.spectrum(kLambdaMin);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.f) lo = std::min(lo, v.spectrum(l));
  return lo;
}

}  // namespace

void check_constant_spectrum_sign(const ParameterList& params, const std::string& name, bool zero_allowed) {
  const Param* p = params.find(name);
  if (!p || p->canonical_type() == "texture") return;
  const float lo = min_value(*params.get_spectrum(name, SpectrumType::Unbounded));
  if (lo > 0.f || (zero_allowed && lo == 0.f)) return;
  params.fail(
      name, fmt::format("must be {} (its smallest value here is {})", zero_allowed ? "non-negative" : "positive", lo));
}

}  // namespace eyetrace
