// The one parameter check (PluginParams) against hand-made tables and lists: every kind of
// mistake is reported with its place and parameter, several at once; defaults come from the
// table; and every registered plugin's table is consistent with itself.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "../support/unity_id.h"
#include "scene/param_spec.h"
#include "scene/registry.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const PluginSpec& spec() {
  static const PluginSpec s{
      "Camera",
      "a test table",
      "—",
      {param::real("fov", 90).open_range(0, 180).with_unit("deg"), param::real("lensradius", 0).at_least(0),
       param::integer("count", 4).range(1, 8), param::string("mapping", "angle").in({"angle", "flat", "retina"}),
       param::reals("window").size(4), param::point3s("P"), param::spectrum("L", 1),
       param::float_texture("roughness", 0).at_least(0), param::real("optional")}};
  return s;
}

Param number(const std::string& type, const std::string& name, std::vector<double> values, int column = 1) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"t.pbrt", 3, column};
  p.numbers = std::move(values);
  return p;
}

Param text(const std::string& type, const std::string& name, const std::string& value) {
  Param p = number(type, name, {});
  p.strings = {value};
  return p;
}

// The diagnostics of checking `params` against spec(); empty when the list passes.
std::vector<Diagnostic> check(std::vector<Param> params) {
  ParameterList list(SourceLoc{"t.pbrt", 3, 1});
  for (Param& p : params) list.add(std::move(p));
  try {
    PluginParams checked(list, spec(), "test");
  } catch (const SceneError& e) {
    return e.diagnostics();
  }
  return {};
}

std::string only_message(std::vector<Param> params) {
  std::vector<Diagnostic> d = check(std::move(params));
  return d.size() == 1 ? d[0].message : fmt::format("{} diagnostics", d.size());
}

TEST(ParamSpec, UnknownNameIsAnErrorWithTheClosestDeclaredName) {
  std::vector<Diagnostic> d = check({number("float", "flov", {45})});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "Camera \"test\": unused parameter \"float flov\" (did you mean \"fov\"?)");
  EXPECT_EQ(d[0].parameter, "flov");
  EXPECT_EQ(d[0].loc.line, 3);
}

TEST(ParamSpec, TypesAndValueCountsAreChecked) {
  EXPECT_EQ(only_message({text("string", "fov", "wide")}),
            "parameter \"fov\" has type \"string\" but must be \"float\"");
  EXPECT_EQ(only_message({number("float", "fov", {1, 2})}), "parameter \"fov\" takes one value, got 2");
  EXPECT_EQ(only_message({number("float", "window", {0, 1, 0})}), "parameter \"window\" takes 4 values, got 3");
  EXPECT_EQ(only_message({number("point3", "P", {0, 1, 0, 1})}), "parameter \"P\" needs a multiple of 3 values, got 4");
  EXPECT_EQ(only_message({number("integer", "count", {2.5})}), "parameter \"count\" value 2.5 is not a 32-bit integer");
  EXPECT_EQ(only_message({number("rgb", "roughness", {1, 1, 1})}),
            "parameter \"roughness\" has type \"rgb\" but must be \"float\" or \"texture\"");
  // pbrt-v4's aliases are their canonical types; every spectrum form is a spectrum.
  EXPECT_TRUE(check({number("point", "P", {0, 0, 0}), number("blackbody", "L", {6500})}).empty());
  EXPECT_TRUE(check({text("texture", "roughness", "bumps")}).empty());  // a texture's existence is the store's
}

TEST(ParamSpec, RangesHonourOpenAndClosedEnds) {
  EXPECT_EQ(only_message({number("float", "fov", {180})}), "parameter \"fov\": 180 deg is outside (0, 180) deg");
  EXPECT_EQ(only_message({number("float", "fov", {0})}), "parameter \"fov\": 0 deg is outside (0, 180) deg");
  EXPECT_TRUE(check({number("float", "fov", {179.999})}).empty());
  EXPECT_TRUE(check({number("float", "lensradius", {0})}).empty());
  EXPECT_EQ(only_message({number("float", "lensradius", {-1e-6})}),
            "parameter \"lensradius\": -1e-06 is outside [0, inf)");
  EXPECT_EQ(only_message({number("integer", "count", {9})}), "parameter \"count\": 9 is outside [1, 8]");
  EXPECT_EQ(only_message({number("float", "roughness", {-0.5})}), "parameter \"roughness\": -0.5 is outside [0, inf)");
  EXPECT_EQ(only_message({number("float", "optional", {1e39})}),
            "parameter \"optional\" value 1e+39 is out of the float range");
}

TEST(ParamSpec, ChoicesAreCheckedWithAHint) {
  EXPECT_EQ(
      only_message({text("string", "mapping", "angel")}),
      "parameter \"mapping\": \"angel\" is not one of \"angle\", \"flat\" or \"retina\" (did you mean \"angle\"?)");
  EXPECT_TRUE(check({text("string", "mapping", "retina")}).empty());
}

TEST(ParamSpec, EveryMistakeOfADirectiveIsReportedAtOnce) {
  std::vector<Diagnostic> d = check({number("float", "fov", {200}, 10), number("float", "flov", {1}, 20),
                                     text("string", "mapping", "x"), number("float", "lensradius", {0}, 40)});
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].parameter, "fov");
  EXPECT_EQ(d[1].parameter, "flov");
  EXPECT_EQ(d[2].parameter, "mapping");
}

TEST(ParamSpec, DefaultsComeFromTheTable) {
  ParameterList list(SourceLoc{"t.pbrt", 1, 1});
  list.add(number("float", "fov", {30}));
  const PluginParams p(list, spec(), "test");
  EXPECT_EQ(p.get_float("fov"), 30.f);
  EXPECT_EQ(p.get_float("lensradius"), 0.f);
  EXPECT_EQ(p.get_int("count"), 4);
  EXPECT_EQ(p.get_string("mapping"), "angle");
  EXPECT_EQ(*p.get_spectrum("L", SpectrumType::Illuminant).rgb, RGB(1.f));
  EXPECT_FALSE(p.has("optional"));
  // Reading an undeclared name, or an absent one without a default, is the plugin's bug.
  EXPECT_THROW(p.get_float("fvo"), std::logic_error);
  EXPECT_THROW(p.get_float("optional"), std::logic_error);
}

// Parameters consumed before the plugin (an Attribute default, MakeNamedMaterial's "type") are
// marked used and may be undeclared, as pbrt-v4 lets a plugin ignore attribute defaults.
TEST(ParamSpec, AlreadyUsedUndeclaredParametersPass) {
  Param attribute = number("float", "radius", {2});
  attribute.used = true;
  EXPECT_TRUE(check({attribute}).empty());
}

bool admits(const ParamSpec& s, double v) {
  if (s.lo && (s.lo_open ? !(v > *s.lo) : !(v >= *s.lo))) return false;
  if (s.hi && (s.hi_open ? !(v < *s.hi) : !(v <= *s.hi))) return false;
  return true;
}

// Every registered plugin's table: unique names, a doc or a unit or a default for each, and
// every declared default inside its own range and among its own choices.
TEST(ParamSpec, EveryRegisteredTableIsConsistent) {
  const std::vector<PluginListing> all = Registry::builtin().listing();
  ASSERT_GT(all.size(), 40u);
  for (const PluginListing& p : all) {
    SCOPED_TRACE(p.kind + " " + p.name);
    EXPECT_FALSE(p.spec->summary.empty());
    EXPECT_FALSE(p.spec->differences.empty());
    std::set<std::string> names;
    for (const ParamSpec& s : p.spec->params) {
      SCOPED_TRACE(s.name);
      EXPECT_TRUE(names.insert(s.name).second) << "declared twice";
      EXPECT_FALSE(s.doc.empty() && s.unit.empty() && s.default_text().empty()) << "says nothing about itself";
      if (!s.has_default) continue;
      if (s.type == ParamType::String) {
        if (!s.choices.empty())
          EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), s.default_string), s.choices.end());
      } else {
        for (double v : s.default_numbers)
          if (s.type == ParamType::Float || s.type == ParamType::Integer) EXPECT_TRUE(admits(s, v)) << v;
      }
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
