#include "scene/param_spec.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace eyetrace {

// ---- the table entries ----

ParamSpec&& ParamSpec::range(double l, double h) && {
  lo = l, hi = h;
  return std::move(*this);
}
ParamSpec&& ParamSpec::open_range(double l, double h) && {
  lo = l, hi = h, lo_open = hi_open = true;
  return std::move(*this);
}
ParamSpec&& ParamSpec::left_open_range(double l, double h) && {
  lo = l, hi = h, lo_open = true;
  return std::move(*this);
}
ParamSpec&& ParamSpec::at_least(double l) && {
  lo = l;
  return std::move(*this);
}
ParamSpec&& ParamSpec::above(double l) && {
  lo = l, lo_open = true;
  return std::move(*this);
}
ParamSpec&& ParamSpec::in(std::vector<std::string> values) && {
  choices = std::move(values);
  return std::move(*this);
}
ParamSpec&& ParamSpec::with_unit(std::string u) && {
  unit = std::move(u);
  return std::move(*this);
}
ParamSpec&& ParamSpec::shown_default(std::string text) && {
  default_doc = std::move(text);
  return std::move(*this);
}
ParamSpec&& ParamSpec::size(int n) && {
  array_size = n;
  return std::move(*this);
}
ParamSpec&& ParamSpec::describe(std::string text) && {
  doc = std::move(text);
  return std::move(*this);
}

std::vector<std::string> ParamSpec::accepted_types() const {
  switch (type) {
    case ParamType::Float: return {"float"};
    case ParamType::Integer: return {"integer"};
    case ParamType::Bool: return {"bool"};
    case ParamType::String: return {"string"};
    case ParamType::Point2: return {"point2"};
    case ParamType::Point3: return {"point3"};
    case ParamType::Vector3: return {"vector3"};
    case ParamType::Normal: return {"normal"};
    case ParamType::Spectrum: return {"rgb", "spectrum", "blackbody"};
    case ParamType::Rgb: return {"rgb"};
    case ParamType::FloatOrSpectrum: return {"float", "rgb", "spectrum", "blackbody"};
    case ParamType::FloatTexture: return {"float", "texture"};
    case ParamType::SpectrumTexture: return {"rgb", "spectrum", "blackbody", "texture"};
    case ParamType::AnyTexture: return {"float", "rgb", "spectrum", "blackbody", "texture"};
  }
  return {};
}

std::string ParamSpec::type_name() const {
  switch (type) {
    case ParamType::Spectrum: return "spectrum";
    case ParamType::Rgb: return "rgb";
    case ParamType::FloatOrSpectrum: return "float";
    case ParamType::FloatTexture: return "float";
    case ParamType::SpectrumTexture: return "spectrum";
    case ParamType::AnyTexture: return "texture";
    default: return accepted_types().front();
  }
}

namespace {

// Numbers as a person writes them (shortest exact form): 90, 0.5, 16777216, 1e+38.
std::string number_text(double v) { return fmt::format("{}", v); }

std::string bound_text(double v) { return std::isinf(v) ? (v > 0 ? "inf" : "-inf") : number_text(v); }

}  // namespace

std::string ParamSpec::default_text() const {
  if (!default_doc.empty()) return default_doc;
  if (!has_default) return "";
  switch (type) {
    case ParamType::Bool: return default_numbers.at(0) != 0.0 ? "true" : "false";
    case ParamType::String: return "\"" + default_string + "\"";
    default: break;
  }
  if (!default_string.empty()) return "\"" + default_string + "\"";
  std::string s;
  for (double v : default_numbers) s += (s.empty() ? "" : ", ") + number_text(v);
  return default_numbers.size() > 1 ? "(" + s + ")" : s;
}

std::string ParamSpec::range_text() const {
  if (!lo && !hi) return "";
  return fmt::format("{}{}, {}{}", lo_open || !lo ? "(" : "[", lo ? bound_text(*lo) : "-inf",
                     hi ? bound_text(*hi) : "inf", hi_open || !hi ? ")" : "]");
}

namespace param {

namespace {
ParamSpec make(std::string name, ParamType type, std::optional<double> def) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = type;
  if (def) {
    s.default_numbers = {*def};
    s.has_default = true;
  }
  return s;
}
ParamSpec make_array(std::string name, ParamType type) {
  ParamSpec s = make(std::move(name), type, std::nullopt);
  s.array = true;
  return s;
}
ParamSpec make_vec3(std::string name, ParamType type, std::optional<Vec3> def) {
  ParamSpec s = make(std::move(name), type, std::nullopt);
  if (def) {
    s.default_numbers = {(*def).x, (*def).y, (*def).z};
    s.has_default = true;
  }
  return s;
}
}  // namespace

ParamSpec real(std::string name, std::optional<double> def) { return make(std::move(name), ParamType::Float, def); }
ParamSpec integer(std::string name, std::optional<int> def) {
  return make(std::move(name), ParamType::Integer, def ? std::optional<double>(*def) : std::nullopt);
}
ParamSpec boolean(std::string name, bool def) { return make(std::move(name), ParamType::Bool, def ? 1.0 : 0.0); }
ParamSpec string(std::string name, std::optional<std::string> def) {
  ParamSpec s = make(std::move(name), ParamType::String, std::nullopt);
  if (def) {
    s.default_string = *def;
    s.has_default = true;
  }
  return s;
}
ParamSpec point3(std::string name, std::optional<Vec3> def) {
  return make_vec3(std::move(name), ParamType::Point3, def);
}
ParamSpec vector3(std::string name, std::optional<Vec3> def) {
  return make_vec3(std::move(name), ParamType::Vector3, def);
}
ParamSpec spectrum(std::string name, std::optional<double> def) {
  return make(std::move(name), ParamType::Spectrum, def);
}
ParamSpec float_or_spectrum(std::string name, std::optional<double> def) {
  return make(std::move(name), ParamType::FloatOrSpectrum, def);
}
ParamSpec float_texture(std::string name, std::optional<double> def) {
  return make(std::move(name), ParamType::FloatTexture, def);
}
ParamSpec spectrum_texture(std::string name, std::optional<double> def) {
  return make(std::move(name), ParamType::SpectrumTexture, def);
}
ParamSpec any_texture(std::string name, std::optional<double> def) {
  return make(std::move(name), ParamType::AnyTexture, def);
}
ParamSpec reals(std::string name) { return make_array(std::move(name), ParamType::Float); }
ParamSpec strings(std::string name) { return make_array(std::move(name), ParamType::String); }
ParamSpec integers(std::string name) { return make_array(std::move(name), ParamType::Integer); }
ParamSpec point2s(std::string name) { return make_array(std::move(name), ParamType::Point2); }
ParamSpec point3s(std::string name) { return make_array(std::move(name), ParamType::Point3); }
ParamSpec normals(std::string name) { return make_array(std::move(name), ParamType::Normal); }
ParamSpec vector3s(std::string name) { return make_array(std::move(name), ParamType::Vector3); }
ParamSpec rgbs(std::string name) { return make_array(std::move(name), ParamType::Rgb); }

}  // namespace param

const ParamSpec* PluginSpec::find(const std::string& name) const {
  for (const ParamSpec& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<ParamSpec> operator+(std::vector<ParamSpec> a, const std::vector<ParamSpec>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// ---- the one check ----

namespace {

// Values per item of a pbrt type; 0 when it varies (spectrum: a constant, pairs or a name).
size_t item_size(const std::string& type) {
  if (type == "point2" || type == "vector2") return 2;
  if (type == "point3" || type == "vector3" || type == "normal" || type == "rgb") return 3;
  if (type == "spectrum") return 0;
  return 1;
}

std::string quoted_list(const std::vector<std::string>& items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i)
    s += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + ("\"" + items[i] + "\"");
  return s;
}

bool in_range(const ParamSpec& s, double v) {
  if (s.lo && (s.lo_open ? !(v > *s.lo) : !(v >= *s.lo))) return false;
  if (s.hi && (s.hi_open ? !(v < *s.hi) : !(v <= *s.hi))) return false;
  return true;
}

// The problem with one given parameter against its declaration, as a message, or "".
std::string problem(const Param& p, const ParamSpec& s) {
  const std::string type = p.canonical_type();
  const std::vector<std::string> accepted = s.accepted_types();
  const std::string name = "parameter \"" + p.name + "\"";
  if (std::find(accepted.begin(), accepted.end(), type) == accepted.end())
    return fmt::format("{} has type \"{}\" but must be {}", name, p.type, quoted_list(accepted));
  const size_t n = p.numbers.size() + p.strings.size() + p.bools.size();
  const size_t item = item_size(type);
  if (n == 0) return name + " has no value";
  if (item > 0 && !s.array && n != item)
    return item == 1 ? fmt::format("{} takes one value, got {}", name, n)
                     : fmt::format("{} takes {} values, got {}", name, item, n);
  if (item > 0 && s.array && n % item != 0)
    return fmt::format("{} needs a multiple of {} values, got {}", name, item, n);
  if (s.array && s.array_size > 0 && n != size_t(s.array_size))
    return fmt::format("{} takes {} values, got {}", name, s.array_size, n);
  for (double v : p.numbers) {
    if (!std::isfinite(v)) return name + " has a non-finite value";
    if (std::abs(v) > 3.0e38) return fmt::format("{} value {} is out of the float range", name, v);
    if (type == "integer" && (v != std::floor(v) || std::abs(v) > 2147483647.0))
      return fmt::format("{} value {} is not a 32-bit integer", name, v);
  }
  // A unit of one word follows the value and the range ("20 mm is outside (0, 10] mm").
  const std::string unit = s.unit.empty() || s.unit.find(' ') != std::string::npos ? "" : " " + s.unit;
  if (type == "float" || type == "integer")
    for (double v : p.numbers)
      if (!in_range(s, v))
        return fmt::format("{}: {}{} is outside {}{}", name, number_text(v), unit, s.range_text(), unit);
  if (!s.choices.empty() && type == "string") {
    const std::string& v = p.strings.at(0);
    if (std::find(s.choices.begin(), s.choices.end(), v) == s.choices.end()) {
      const std::string hint = closest_match(v, s.choices);
      return fmt::format("{}: \"{}\" is not one of {}{}", name, v, quoted_list(s.choices),
                         hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint));
    }
  }
  return "";
}

}  // namespace

PluginParams::PluginParams(const ParameterList& list, const PluginSpec& spec, const std::string& plugin)
    : list_(list), spec_(spec) {
  std::vector<std::string> names;
  for (const ParamSpec& s : spec.params) names.push_back(s.name);
  std::vector<Diagnostic> found;
  for (const Param& p : list.params()) {
    const ParamSpec* s = spec.find(p.name);
    // Already used: consumed before the plugin (MakeNamedMaterial's "type", Attribute defaults,
    // which pbrt-v4 lets a plugin ignore).
    if (!s && p.used) continue;
    if (!s) {
      const std::string hint = closest_match(p.name, names);
      found.push_back(
          Diagnostic{p.loc, p.name, Severity::Error,
                     fmt::format("{} \"{}\": unused parameter \"{} {}\"{}", spec.directive, plugin, p.type, p.name,
                                 hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint))});
      continue;
    }
    p.used = true;
    const std::string why = problem(p, *s);
    if (!why.empty()) found.push_back(Diagnostic{p.loc, p.name, Severity::Error, why});
  }
  if (!found.empty()) throw SceneError(std::move(found));
}

bool PluginParams::has(const std::string& name) const {
  declared(name);
  return list_.has(name);
}

void PluginParams::fail(const std::string& name, const std::string& message) const { list_.fail(name, message); }
void PluginParams::fail_missing_file(const std::string& name, const std::string& message) const {
  list_.fail_missing_file(name, message);
}

void PluginParams::warn_param(const std::string& name, const std::string& message) const {
  const Param* p = list_.find(name);
  warn(p ? p->loc : list_.loc(), fmt::format("parameter \"{}\": {}", name, message));
}

const ParamSpec& PluginParams::declared(const std::string& name) const {
  if (const ParamSpec* s = spec_.find(name)) return *s;
  throw std::logic_error(fmt::format("{} plugin reads undeclared parameter \"{}\"", spec_.directive, name));
}

const ParamSpec& PluginParams::with_default(const std::string& name) const {
  const ParamSpec& s = declared(name);
  if (!s.has_default)
    throw std::logic_error(fmt::format("{} parameter \"{}\" has no declared default", spec_.directive, name));
  return s;
}

double PluginParams::default_number(const std::string& name) const { return with_default(name).default_numbers.at(0); }

float PluginParams::get_float(const std::string& name) const {
  return has(name) ? list_.get_float(name, 0.f) : float(default_number(name));
}

double PluginParams::get_double(const std::string& name) const {
  if (!has(name)) return default_number(name);
  list_.get_float(name, 0.f);  // type and count checks
  return list_.find(name)->numbers.at(0);
}

int PluginParams::get_int(const std::string& name) const {
  return has(name) ? list_.get_int(name, 0) : int(default_number(name));
}

bool PluginParams::get_bool(const std::string& name) const {
  return has(name) ? list_.get_bool(name, false) : default_number(name) != 0.0;
}

std::string PluginParams::get_string(const std::string& name) const {
  return has(name) ? list_.get_string(name, "") : with_default(name).default_string;
}

static Vec3 vec3_default(const ParamSpec& s) {
  return Vec3(float(s.default_numbers.at(0)), float(s.default_numbers.at(1)), float(s.default_numbers.at(2)));
}

Vec3 PluginParams::get_point3(const std::string& name) const {
  return has(name) ? list_.get_point3(name, Vec3(0.f)) : vec3_default(with_default(name));
}

Vec3 PluginParams::get_vector3(const std::string& name) const {
  return has(name) ? list_.get_vector3(name, Vec3(0.f)) : vec3_default(with_default(name));
}

SpectrumValue PluginParams::get_spectrum(const std::string& name, SpectrumType type) const {
  if (has(name)) return *list_.get_spectrum(name, type);
  return {RGB(float(default_number(name))), {}};
}

float PluginParams::get_spectrum_at(const std::string& name, float lambda_nm) const {
  return has(name) ? list_.get_spectrum_at(name, lambda_nm, 0.f) : float(default_number(name));
}

std::vector<float> PluginParams::get_floats(const std::string& name) const {
  declared(name);
  return list_.get_floats(name);
}
std::vector<int> PluginParams::get_ints(const std::string& name) const {
  declared(name);
  return list_.get_ints(name);
}
std::vector<Vec2> PluginParams::get_point2s(const std::string& name) const {
  declared(name);
  return list_.get_point2s(name);
}
std::vector<Vec3> PluginParams::get_point3s(const std::string& name) const {
  declared(name);
  return list_.get_point3s(name);
}
std::vector<RGB> PluginParams::get_rgbs(const std::string& name) const {
  declared(name);
  return list_.get_rgbs(name);
}
std::vector<Vec3> PluginParams::get_normals(const std::string& name) const {
  declared(name);
  return list_.get_normals(name);
}
std::vector<Vec3> PluginParams::get_vector3s(const std::string& name) const {
  declared(name);
  return list_.get_vector3s(name);
}

}  // namespace eyetrace
