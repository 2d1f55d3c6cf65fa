// Declared parameters. Every plugin states its parameters once, in a table next to its
// factory: name, type, default, valid range or choices, unit and a one-line doc. From that
// table one shared code path (PluginParams' constructor) checks a directive's parameter list:
// unknown names (with a "did you mean"), types, value counts, ranges and choices, reporting
// every mistake at once. Factories then read values through PluginParams, whose defaults come
// from the table, and `eyetrace plugins` and the docs' parameter tables are printed from it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/params.h"

namespace eyetrace {

// What a parameter accepts, as pbrt-v4 types.
enum class ParamType {
  Float,            // float
  Integer,          // integer
  Bool,             // bool
  String,           // string
  Point2,           // point2
  Point3,           // point3
  Vector3,          // vector3
  Normal,           // normal
  Spectrum,         // rgb, spectrum or blackbody
  Rgb,              // rgb only (arrays of colours)
  FloatOrSpectrum,  // float, or rgb/spectrum/blackbody (read at one wavelength)
  FloatTexture,     // float constant or "texture NAME"
  SpectrumTexture,  // rgb/spectrum/blackbody constant or "texture NAME"
  AnyTexture,       // float or spectrum constant, or "texture NAME" (textures of either kind)
};

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Float;
  bool array = false;                   // any number of values (point3 P, integer indices); else exactly one item
  int array_size = 0;                   // arrays: exact number of values if > 0
  std::vector<double> default_numbers;  // numeric, bool (0/1) and point defaults
  std::string default_string;
  bool has_default = false;
  std::string default_doc;  // shown instead of the value: "required", "model's", "−radius"
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;
  std::vector<std::string> choices;  // strings: the accepted values
  std::string unit;                  // "mm", "deg", "D", "nm", "scene units", "pixels"
  std::string doc;

  // Fluent setters for the tables.
  ParamSpec&& range(double l, double h) &&;            // [l, h]
  ParamSpec&& open_range(double l, double h) &&;       // (l, h)
  ParamSpec&& at_least(double l) &&;                   // [l, inf)
  ParamSpec&& above(double l) &&;                      // (l, inf)
  ParamSpec&& left_open_range(double l, double h) &&;  // (l, h]
  ParamSpec&& in(std::vector<std::string> values) &&;
  ParamSpec&& with_unit(std::string u) &&;
  ParamSpec&& shown_default(std::string text) &&;
  ParamSpec&& size(int n) &&;
  ParamSpec&& describe(std::string text) &&;

  std::vector<std::string> accepted_types() const;  // pbrt-v4 type names, canonical
  std::string type_name() const;                    // "float", "spectrum texture", ...
  std::string default_text() const;                 // for listings; "" when none
  std::string range_text() const;                   // "(0, 180)", "[0, inf)", "" when none
};

// Table entries, one constructor per type (defaults typed as the reader returns them).
namespace param {
ParamSpec real(std::string name, std::optional<double> def = std::nullopt);
ParamSpec integer(std::string name, std::optional<int> def = std::nullopt);
ParamSpec boolean(std::string name, bool def);
ParamSpec string(std::string name, std::optional<std::string> def = std::nullopt);
ParamSpec point3(std::string name, std::optional<Vec3> def = std::nullopt);
ParamSpec vector3(std::string name, std::optional<Vec3> def = std::nullopt);
ParamSpec spectrum(std::string name, std::optional<double> def = std::nullopt);
ParamSpec float_or_spectrum(std::string name, std::optional<double> def = std::nullopt);
ParamSpec float_texture(std::string name, std::optional<double> def = std::nullopt);
ParamSpec spectrum_texture(std::string name, std::optional<double> def = std::nullopt);
ParamSpec any_texture(std::string name, std::optional<double> def = std::nullopt);
ParamSpec reals(std::string name);
ParamSpec strings(std::string name);
ParamSpec integers(std::string name);
ParamSpec point2s(std::string name);
ParamSpec point3s(std::string name);
ParamSpec normals(std::string name);
ParamSpec vector3s(std::string name);
// Any number of RGB triples ("rgb" only: grids of colours, as pbrt-v4's rgbgrid medium).
ParamSpec rgbs(std::string name);
}  // namespace param

// One plugin's (or several plugins') declaration: what `eyetrace plugins` lists.
struct PluginSpec {
  std::string directive;    // "Camera", "Shape", "Texture", ... (for messages)
  std::string summary;      // one line: what it is
  std::string differences;  // how it differs from pbrt-v4 ("—" when it does not)
  std::vector<ParamSpec> params;
  // Where the parameters are described at length (a docs link); the directive's plugin table
  // then lists their names only.
  std::string details;

  const ParamSpec* find(const std::string& name) const;
};

// Concatenation of parameter groups shared by several plugins (roughness, texture mapping).
std::vector<ParamSpec> operator+(std::vector<ParamSpec> a, const std::vector<ParamSpec>& b);

// A directive's parameters checked against a plugin's table; the reader factories use.
class PluginParams {
 public:
  // Checks `list` against `spec` (the one shared path): every parameter must be declared,
  // of an accepted type, with the right number of values, in range and among the choices.
  // Throws one SceneError listing every problem. `plugin` names the plugin in messages.
  PluginParams(const ParameterList& list, const PluginSpec& spec, const std::string& plugin);

  const ParameterList& list() const { return list_; }
  const PluginSpec& spec() const { return spec_; }
  const SourceLoc& loc() const { return list_.loc(); }
  bool has(const std::string& name) const;
  [[noreturn]] void fail(const std::string& name, const std::string& message) const;
  [[noreturn]] void fail_missing_file(const std::string& name, const std::string& message) const;
  void warn_param(const std::string& name, const std::string& message) const;

  // Values; an absent parameter gives the table's default. Asking for an undeclared name,
  // or for an absent one without a default, is a programming error (std::logic_error).
  float get_float(const std::string& name) const;
  double get_double(const std::string& name) const;  // full precision of the scene text
  int get_int(const std::string& name) const;
  bool get_bool(const std::string& name) const;
  std::string get_string(const std::string& name) const;
  Vec3 get_point3(const std::string& name) const;
  Vec3 get_vector3(const std::string& name) const;
  // A spectrum parameter; absent: the declared default number c as RGB (c, c, c).
  SpectrumValue get_spectrum(const std::string& name, SpectrumType type) const;
  float get_spectrum_at(const std::string& name, float lambda_nm) const;
  std::vector<float> get_floats(const std::string& name) const;
  std::vector<int> get_ints(const std::string& name) const;
  std::vector<Vec2> get_point2s(const std::string& name) const;
  std::vector<Vec3> get_point3s(const std::string& name) const;
  std::vector<Vec3> get_normals(const std::string& name) const;
  std::vector<Vec3> get_vector3s(const std::string& name) const;
  std::vector<RGB> get_rgbs(const std::string& name) const;
  // The declared default of a numeric parameter (for textures made from it).
  double default_number(const std::string& name) const;

 private:
  const ParamSpec& declared(const std::string& name) const;
  const ParamSpec& with_default(const std::string& name) const;
  const ParameterList& list_;
  const PluginSpec& spec_;
};

}  // namespace eyetrace
