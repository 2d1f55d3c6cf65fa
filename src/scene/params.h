// A directive's typed parameter list ("float fov" [45], "rgb reflectance" [.5 .5 .5], ...),
// with typed lookups that mark a parameter used. Plugins read it through PluginParams
// (scene/param_spec.h), which first checks it against the plugin's declared parameters.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/spectrum.h"

namespace eyetrace {

struct Param {
  std::string type;  // as written: float integer bool string point2 vector2 point3 vector3
                     // normal rgb spectrum blackbody texture (point, vector, normal3, color too)
  std::string name;
  SourceLoc loc;
  std::vector<double> numbers;       // numeric values (float, integer, points, rgb, spectrum pairs)
  std::vector<std::string> strings;  // string, texture, named spectrum values
  std::vector<bool> bools;
  mutable bool used = false;
  // Canonical type: "point" -> "point3", "vector" -> "vector3", "normal3" -> "normal", "color" -> "rgb".
  std::string canonical_type() const;
};

class ParameterList {
 public:
  ParameterList() = default;
  explicit ParameterList(SourceLoc directive_loc) : loc_(std::move(directive_loc)) {}

  // A repeated name of the same type replaces the earlier value with a warning (pbrt-v4 uses
  // the last); of another type it is an error at the second occurrence.
  void add(Param p);
  const SourceLoc& loc() const { return loc_; }
  const std::vector<Param>& params() const { return params_; }
  bool has(const std::string& name) const { return find(name) != nullptr; }
  const Param* find(const std::string& name) const;

  // Single values. A parameter of the same name but another type is an error naming both.
  float get_float(const std::string& name, float def) const;
  int get_int(const std::string& name, int def) const;
  bool get_bool(const std::string& name, bool def) const;
  std::string get_string(const std::string& name, const std::string& def) const;
  Vec3 get_point3(const std::string& name, const Vec3& def) const;
  Vec3 get_vector3(const std::string& name, const Vec3& def) const;
  // An "rgb", "spectrum" or "blackbody" parameter; nullopt if absent. `type` is what the
  // plugin uses it as (a spectrum given as such that is an Illuminant is normalised; an RGB
  // read as an Albedo outside [0, 1] is warned about, scene/spectrum_param.h).
  std::optional<SpectrumValue> get_spectrum(const std::string& name, SpectrumType type) const;
  // A "spectrum", "rgb" (its green value) or "float" parameter at one wavelength; def if absent.
  float get_spectrum_at(const std::string& name, float lambda_nm, float def) const;
  // Name of a "texture" parameter, or "" when absent.
  std::string get_texture(const std::string& name) const;

  // Arrays (empty if absent).
  std::vector<float> get_floats(const std::string& name) const;
  std::vector<int> get_ints(const std::string& name) const;
  std::vector<Vec2> get_point2s(const std::string& name) const;
  std::vector<Vec3> get_point3s(const std::string& name) const;
  std::vector<Vec3> get_normals(const std::string& name) const;
  std::vector<Vec3> get_vector3s(const std::string& name) const;
  std::vector<RGB> get_rgbs(const std::string& name) const;

  // Errors at a parameter's location (or the directive's if the parameter is absent).
  [[noreturn]] void fail(const std::string& name, const std::string& message) const;
  // The same for a file the parameter names that does not exist (DiagnosticKind::MissingFile).
  [[noreturn]] void fail_missing_file(const std::string& name, const std::string& message) const;
  void mark_all_used() const;

 private:
  const Param* lookup(const std::string& name, const char* type, size_t min_values) const;
  SourceLoc loc_;
  std::vector<Param> params_;
};

}  // namespace eyetrace
