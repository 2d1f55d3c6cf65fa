#include "scene/params.h"

#include <cmath>

#include "scene/spectrum_param.h"

namespace eyetrace {

std::string Param::canonical_type() const {
  if (type == "point") return "point3";
  if (type == "vector") return "vector3";
  if (type == "normal3") return "normal";
  if (type == "color") return "rgb";
  return type;
}

// pbrt-v4 keeps every copy of a repeated parameter and looks them up newest first (its
// ParameterDictionary reverses the list), so the last value of a type wins; the collection's
// watercolor/camera-2.pbrt relies on it. A repeat with another type is an error as before:
// pbrt-v4 would report the copy its plugin does not read as unused.
void ParameterList::add(Param p) {
  for (auto& prev : params_) {
    if (prev.name != p.name) continue;
    if (prev.canonical_type() != p.canonical_type())
      eyetrace::fail(p.loc, "parameter \"{}\" given twice (first at {})", p.name, prev.loc.to_string());
    warn(p.loc, fmt::format("parameter \"{}\" given again (first at {}): the last value is used, as pbrt-v4 does",
                            p.name, prev.loc.to_string()));
    prev = std::move(p);
    return;
  }
  params_.push_back(std::move(p));
}

const Param* ParameterList::find(const std::string& name) const {
  for (const auto& p : params_)
    if (p.name == name) return &p;
  return nullptr;
}

void ParameterList::fail(const std::string& name, const std::string& message) const {
  const Param* p = find(name);
  throw_parameter_error(p ? p->loc : loc_, name, fmt::format("parameter \"{}\": {}", name, message));
}

void ParameterList::fail_missing_file(const std::string& name, const std::string& message) const {
  const Param* p = find(name);
  throw_missing_file(p ? p->loc : loc_, name, fmt::format("parameter \"{}\": {}", name, message));
}

// Values are parsed as doubles but used as floats: one beyond the float range would become
// infinite (a point light at infinity, an infinite radiance) without a word.
static void check_numbers(const Param& p) {
  for (double v : p.numbers) {
    if (!std::isfinite(v)) eyetrace::fail(p.loc, "parameter \"{}\" has a non-finite value", p.name);
    if (std::abs(v) > 3.0e38) eyetrace::fail(p.loc, "parameter \"{}\" value {} is out of the float range", p.name, v);
  }
}

const Param* ParameterList::lookup(const std::string& name, const char* type, size_t min_values) const {
  const Param* p = find(name);
  if (!p) return nullptr;
  std::string t = p->canonical_type();
  if (t != type) eyetrace::fail(p->loc, "parameter \"{}\" has type \"{}\" but must be \"{}\"", name, p->type, type);
  p->used = true;
  size_t n = p->numbers.size() + p->strings.size() + p->bools.size();
  if (n < min_values)
    eyetrace::fail(p->loc, "parameter \"{}\" needs at least {} value(s), got {}", name, min_values, n);
  check_numbers(*p);
  return p;
}

float ParameterList::get_float(const std::string& name, float def) const {
  const Param* p = lookup(name, "float", 1);
  if (!p) return def;
  if (p->numbers.size() != 1)
    eyetrace::fail(p->loc, "parameter \"{}\" takes one value, got {}", name, p->numbers.size());
  double v = p->numbers[0];
  if (std::abs(v) > 3.0e38) eyetrace::fail(p->loc, "parameter \"{}\" value {} is out of the float range", name, v);
  return float(v);
}

int ParameterList::get_int(const std::string& name, int def) const {
  const Param* p = lookup(name, "integer", 1);
  if (!p) return def;
  if (p->numbers.size() != 1)
    eyetrace::fail(p->loc, "parameter \"{}\" takes one value, got {}", name, p->numbers.size());
  double v = p->numbers[0];
  if (v != std::floor(v) || std::abs(v) > 2147483647.0)
    eyetrace::fail(p->loc, "parameter \"{}\" value {} is not a 32-bit integer", name, v);
  return int(v);
}

bool ParameterList::get_bool(const std::string& name, bool def) const {
  const Param* p = lookup(name, "bool", 1);
  if (!p) return def;
  if (p->bools.size() != 1) eyetrace::fail(p->loc, "parameter \"{}\" takes one value", name);
  return p->bools[0];
}

std::string ParameterList::get_string(const std::string& name, const std::string& def) const {
  const Param* p = lookup(name, "string", 1);
  if (!p) return def;
  if (p->strings.size() != 1) eyetrace::fail(p->loc, "parameter \"{}\" takes one value", name);
  return p->strings[0];
}

static Vec3 vec3_of(const Param& p) {
  if (p.numbers.size() != 3) eyetrace::fail(p.loc, "parameter \"{}\" takes 3 values, got {}", p.name, p.numbers.size());
  return Vec3(float(p.numbers[0]), float(p.numbers[1]), float(p.numbers[2]));
}

Vec3 ParameterList::get_point3(const std::string& name, const Vec3& def) const {
  const Param* p = lookup(name, "point3", 3);
  return p ? vec3_of(*p) : def;
}

Vec3 ParameterList::get_vector3(const std::string& name, const Vec3& def) const {
  const Param* p = lookup(name, "vector3", 3);
  return p ? vec3_of(*p) : def;
}

std::optional<SpectrumValue> ParameterList::get_spectrum(const std::string& name, SpectrumType type) const {
  const Param* p = find(name);
  if (!p) return std::nullopt;
  std::string t = p->canonical_type();
  if (t != "rgb" && t != "spectrum" && t != "blackbody")
    eyetrace::fail(p->loc, "parameter \"{}\" has type \"{}\" but must be \"rgb\", \"spectrum\" or \"blackbody\"", name,
                   p->type);
  if (t == "rgb") lookup(name, "rgb", 3);
  p->used = true;
  check_numbers(*p);
  SpectrumValue v = spectrum_param_value(*p, type);
  if (type == SpectrumType::Albedo && v.rgb) warn_if_not_reflectance(*p, *v.rgb);
  return v;
}

float ParameterList::get_spectrum_at(const std::string& name, float lambda_nm, float def) const {
  const Param* p = find(name);
  if (!p) return def;
  p->used = true;
  check_numbers(*p);
  return spectrum_param_at(*p, lambda_nm);
}

std::string ParameterList::get_texture(const std::string& name) const {
  const Param* p = find(name);
  if (!p || p->canonical_type() != "texture") return "";
  lookup(name, "texture", 1);
  return p->strings.at(0);
}

std::vector<float> ParameterList::get_floats(const std::string& name) const {
  const Param* p = lookup(name, "float", 0);
  std::vector<float> out;
  if (p)
    for (double v : p->numbers) out.push_back(float(v));
  return out;
}

std::vector<int> ParameterList::get_ints(const std::string& name) const {
  const Param* p = lookup(name, "integer", 0);
  std::vector<int> out;
  if (!p) return out;
  for (double v : p->numbers) {
    if (v != std::floor(v) || std::abs(v) > 2147483647.0)
      eyetrace::fail(p->loc, "parameter \"{}\" value {} is not a 32-bit integer", name, v);
    out.push_back(int(v));
  }
  return out;
}

template <int N, typename V>
static std::vector<V> tuples(const Param* p) {
  std::vector<V> out;
  if (!p) return out;
  if (p->numbers.size() % N != 0)
    eyetrace::fail(p->loc, "parameter \"{}\" needs a multiple of {} values, got {}", p->name, N, p->numbers.size());
  for (size_t i = 0; i < p->numbers.size(); i += N) {
    V v;
    for (int k = 0; k < N; ++k) v[k] = float(p->numbers[i + k]);
    out.push_back(v);
  }
  return out;
}

std::vector<Vec2> ParameterList::get_point2s(const std::string& name) const {
  return tuples<2, Vec2>(lookup(name, "point2", 0));
}
std::vector<Vec3> ParameterList::get_point3s(const std::string& name) const {
  return tuples<3, Vec3>(lookup(name, "point3", 0));
}
std::vector<Vec3> ParameterList::get_normals(const std::string& name) const {
  return tuples<3, Vec3>(lookup(name, "normal", 0));
}
std::vector<Vec3> ParameterList::get_vector3s(const std::string& name) const {
  return tuples<3, Vec3>(lookup(name, "vector3", 0));
}
std::vector<RGB> ParameterList::get_rgbs(const std::string& name) const {
  return tuples<3, RGB>(lookup(name, "rgb", 0));
}

void ParameterList::mark_all_used() const {
  for (const auto& p : params_) p.used = true;
}

}  // namespace eyetrace
