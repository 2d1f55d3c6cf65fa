// `eyetrace plugins`: every plugin and its declared parameters, from the tables the plugins
// state next to their factories (scene/param_spec.h). As text, as JSON (--json), or as the
// Markdown tables of docs/scene-format.md and docs/eye-camera.md (--markdown), which
// tools/gen-docs writes into the docs and a test compares.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "scene/registry.h"

namespace eyetrace {

namespace {

struct PluginsArgs {
  bool json = false;
  std::string markdown;         // a directive: its plugin table
  std::string markdown_params;  // a plugin name: its parameter table
};

// Plugins that share a table (perspective, thinlens, pinhole; the eye models; a texture's
// float and spectrum kinds) are one group, named in registration order.
struct Group {
  std::string directive;
  std::vector<std::string> names;
  const PluginSpec* spec;
};

std::vector<Group> groups() {
  std::vector<Group> out;
  for (const PluginListing& p : Registry::builtin().listing()) {
    auto same = [&](const Group& g) { return g.spec == p.spec; };
    auto it = std::find_if(out.begin(), out.end(), same);
    if (it == out.end()) {
      out.push_back(Group{p.spec->directive, {p.name}, p.spec});
    } else if (std::find(it->names.begin(), it->names.end(), p.name) == it->names.end()) {
      it->names.push_back(p.name);
    }
  }
  return out;
}

std::string join(const std::vector<std::string>& items, const std::string& sep, const std::string& quote = "") {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : sep) + quote + i + quote;
  return s;
}

// "deg, (0, 180)" or "" when a parameter has neither unit nor range.
std::string unit_and_range(const ParamSpec& p) {
  std::vector<std::string> parts;
  if (!p.unit.empty()) parts.push_back(p.unit);
  if (!p.range_text().empty()) parts.push_back(p.range_text());
  return join(parts, ", ");
}

// "`float fov` 90 (deg, (0, 180)): across the shorter image axis"
std::string param_markdown(const ParamSpec& p) {
  std::string s = fmt::format("`{} {}`", p.type_name(), p.name);
  if (!p.default_text().empty()) s += " " + p.default_text();
  if (const std::string u = unit_and_range(p); !u.empty()) s += " (" + u + ")";
  std::vector<std::string> says;
  if (!p.choices.empty()) says.push_back(join(p.choices, ", ", "`"));
  if (!p.doc.empty()) says.push_back(p.doc);
  if (!says.empty()) s += ": " + join(says, "; ");
  return s;
}

int print_markdown(const std::string& directive) {
  std::string rows;
  for (const Group& g : groups()) {
    if (g.directive != directive) continue;
    std::vector<std::string> params;
    for (const ParamSpec& p : g.spec->params)
      params.push_back(g.spec->details.empty() ? param_markdown(p) : fmt::format("`{} {}`", p.type_name(), p.name));
    std::string cell = params.empty() ? "none" : join(params, g.spec->details.empty() ? "<br>" : ", ");
    if (!g.spec->details.empty()) cell += ": see " + g.spec->details;
    rows += fmt::format("| {} | {} | {} |\n", join(g.names, ", ", "`"), cell, g.spec->differences);
  }
  if (rows.empty()) throw_error(fmt::format("plugins --markdown: no plugins of directive \"{}\"", directive));
  fmt::print("| name | parameters | differences from pbrt-v4 |\n|---|---|---|\n{}", rows);
  return 0;
}

int print_markdown_params(const std::string& name) {
  for (const PluginListing& p : Registry::builtin().listing()) {
    if (p.name != name) continue;
    fmt::print("| parameter | default | meaning |\n|---|---|---|\n");
    for (const ParamSpec& s : p.spec->params) {
      std::string meaning = s.doc;
      if (!s.choices.empty()) meaning = join(s.choices, ", ", "`") + (meaning.empty() ? "" : ". " + meaning);
      if (const std::string u = unit_and_range(s); !u.empty()) meaning = u + (meaning.empty() ? "" : ". " + meaning);
      fmt::print("| `{} {}` | {} | {} |\n", s.type_name(), s.name, s.default_text().empty() ? "—" : s.default_text(),
                 meaning);
    }
    return 0;
  }
  throw_error(fmt::format("plugins --markdown-params: no plugin named \"{}\"", name));
}

nlohmann::json param_json(const ParamSpec& p) {
  nlohmann::json j{{"name", p.name}, {"type", p.type_name()}, {"accepts", p.accepted_types()}, {"array", p.array},
                   {"unit", p.unit}, {"doc", p.doc},          {"default", p.default_text()}};
  if (p.array_size > 0) j["size"] = p.array_size;
  if (p.lo) j["min"] = {{"value", *p.lo}, {"open", p.lo_open}};
  if (p.hi) j["max"] = {{"value", *p.hi}, {"open", p.hi_open}};
  if (!p.choices.empty()) j["choices"] = p.choices;
  return j;
}

int print_plugins(bool json) {
  nlohmann::json all = nlohmann::json::array();
  for (const Group& g : groups()) {
    if (json) {
      nlohmann::json params = nlohmann::json::array();
      for (const ParamSpec& p : g.spec->params) params.push_back(param_json(p));
      all.push_back({{"directive", g.directive},
                     {"names", g.names},
                     {"summary", g.spec->summary},
                     {"differences", g.spec->differences},
                     {"parameters", params}});
      continue;
    }
    fmt::print("{} {}: {}\n", g.directive, join(g.names, ", ", "\""), g.spec->summary);
    for (const ParamSpec& p : g.spec->params) {
      std::string line = fmt::format("  {} {}", p.type_name(), p.name);
      if (!p.default_text().empty()) line += " = " + p.default_text();
      if (const std::string u = unit_and_range(p); !u.empty()) line += " [" + u + "]";
      if (!p.choices.empty()) line += " {" + join(p.choices, ", ") + "}";
      if (!p.doc.empty()) line += ": " + p.doc;
      fmt::print("{}\n", line);
    }
  }
  if (json) fmt::print("{}\n", all.dump(2));
  return 0;
}

}  // namespace

CommandRunner add_plugins_command(CLI::App& app) {
  auto args = std::make_shared<PluginsArgs>();
  CLI::App* c = app.add_subcommand("plugins", "List every plugin and its parameters (names, types, defaults, ranges)");
  c->add_flag("--json", args->json, "Print the list as JSON");
  c->add_option("--markdown", args->markdown,
                "Print the Markdown table of one directive's plugins (Camera, Sampler, PixelFilter, Shape, Material, "
                "Texture, LightSource, AreaLightSource, Integrator, Film), as in docs/scene-format.md");
  c->add_option("--markdown-params", args->markdown_params,
                "Print the Markdown parameter table of one plugin (e.g. eye), as in docs/eye-camera.md");
  return [args] {
    if (!args->markdown.empty()) return print_markdown(args->markdown);
    if (!args->markdown_params.empty()) return print_markdown_params(args->markdown_params);
    return print_plugins(args->json);
  };
}

}  // namespace eyetrace
