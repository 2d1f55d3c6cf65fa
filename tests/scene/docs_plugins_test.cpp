// The "## Plugins" section of docs/scene-format.md against the plugin registry, so the
// documentation cannot fall behind register_builtin_plugins(): every registered name is in its
// directive's table, every name a table lists is registered, and no name the "Not supported"
// table lists is registered.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../support/unity_id.h"
#include "scene/registry.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using NameSet = std::set<std::string>;

std::string read_doc() {
  const std::string path = std::string(EYETRACE_SOURCE_DIR) + "/docs/scene-format.md";
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// From the "## Plugins" heading to the next level-2 heading (or the end); empty if absent.
std::vector<std::string> plugins_section(const std::string& doc) {
  std::vector<std::string> section;
  bool inside = false;
  for (const std::string& line : lines_of(doc)) {
    if (starts_with(line, "## ")) inside = line == "## Plugins";
    if (inside) section.push_back(line);
  }
  return section;
}

std::string first_word(const std::string& s) {
  std::istringstream in(s);
  std::string word;
  in >> word;
  return word;
}

// Lines of each "### Heading ..." subsection, keyed by the heading's first word.
std::map<std::string, std::vector<std::string>> subsections(const std::vector<std::string>& section) {
  std::map<std::string, std::vector<std::string>> out;
  std::string current;
  for (const std::string& line : section) {
    if (starts_with(line, "### ")) {
      current = first_word(line.substr(4));
      out[current];
    } else if (!current.empty()) {
      out[current].push_back(line);
    }
  }
  return out;
}

// The cells of a table row "| a | b |"; empty for any other line.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  if (!starts_with(line, "|")) return cells;
  std::string cell;
  for (size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

// Every `backquoted` token of `text`.
NameSet backquoted(const std::string& text) {
  NameSet names;
  size_t open = text.find('`');
  while (open != std::string::npos) {
    size_t close = text.find('`', open + 1);
    if (close == std::string::npos) break;
    names.insert(text.substr(open + 1, close - open - 1));
    open = text.find('`', close + 1);
  }
  return names;
}

// Backquoted names in cell `column` of every table row (header and separator rows have none).
NameSet names_in_column(const std::vector<std::string>& lines, size_t column) {
  NameSet names;
  for (const std::string& line : lines) {
    std::vector<std::string> cells = cells_of(line);
    if (cells.size() > column) names.merge(backquoted(cells[column]));
  }
  return names;
}

template <typename Table>
NameSet keys_of(const Table& table) {
  NameSet names;
  for (const auto& e : table.entries) names.insert(e.name);
  return names;
}

// The registry's plugin names per directive keyword, the doc's subsection headings.
std::map<std::string, NameSet> registered_by_directive(const Registry& r) {
  NameSet textures = keys_of(r.float_textures);
  textures.merge(keys_of(r.spectrum_textures));
  return {{"Camera", keys_of(r.cameras)},        {"Sampler", keys_of(r.samplers)},
          {"PixelFilter", keys_of(r.filters)},   {"Shape", keys_of(r.shapes)},
          {"Material", keys_of(r.materials)},    {"Texture", textures},
          {"LightSource", keys_of(r.lights)},    {"AreaLightSource", keys_of(r.area_lights)},
          {"MakeNamedMedium", keys_of(r.media)}, {"Integrator", keys_of(r.integrators)}};
}

// "Directive name" for every registered plugin not in the first column of its directive's table.
NameSet undocumented(const std::string& doc, const Registry& r) {
  auto tables = subsections(plugins_section(doc));
  NameSet missing;
  for (const auto& [directive, registered] : registered_by_directive(r)) {
    NameSet listed = names_in_column(tables[directive], 0);
    for (const std::string& name : registered)
      if (!listed.count(name)) missing.insert(directive + " " + name);
  }
  return missing;
}

std::string joined(const NameSet& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string erase_all(std::string text, const std::string& what) {
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at)) text.erase(at, what.size());
  return text;
}

TEST(DocsPlugins, EveryRegisteredPluginIsListed) {
  const Registry& r = Registry::builtin();
  ASSERT_FALSE(r.shapes.entries.empty());
  NameSet missing = undocumented(read_doc(), r);
  EXPECT_TRUE(missing.empty()) << "docs/scene-format.md, section Plugins, lacks: " << joined(missing);
}

// The check itself: names removed from a copy of the doc are reported, and only those, also
// from a cell that lists several cameras.
TEST(DocsPlugins, CheckReportsRemovedNames) {
  const Registry& r = Registry::builtin();
  const std::string doc = read_doc();
  ASSERT_TRUE(undocumented(doc, r).empty());
  std::string cut = erase_all(doc, "`sphere`");
  cut = erase_all(cut, "`navarro`");
  EXPECT_EQ(undocumented(cut, r), (NameSet{"Camera navarro", "Shape sphere"}));
  size_t registered = 0;
  for (const auto& [directive, names] : registered_by_directive(r)) registered += names.size();
  EXPECT_EQ(undocumented("# A doc without a Plugins section\n", r).size(), registered);
}

TEST(DocsPlugins, EveryListedPluginIsRegistered) {
  auto tables = subsections(plugins_section(read_doc()));
  for (const auto& [directive, registered] : registered_by_directive(Registry::builtin())) {
    ASSERT_TRUE(tables.count(directive)) << "no \"### " << directive << "\" table";
    for (const std::string& name : names_in_column(tables[directive], 0))
      EXPECT_TRUE(registered.count(name)) << directive << " \"" << name << "\" is documented but not registered";
  }
}

// Rows "| `Directive` | `name`, ... |": each rejected name must really be unknown to the registry.
TEST(DocsPlugins, UnsupportedNamesAreNotRegistered) {
  auto tables = subsections(plugins_section(read_doc()));
  ASSERT_TRUE(tables.count("Not")) << "no \"### Not supported\" table";
  auto registered = registered_by_directive(Registry::builtin());
  size_t rows = 0;
  for (const std::string& line : tables["Not"]) {
    std::vector<std::string> cells = cells_of(line);
    NameSet directive = cells.size() >= 2 ? backquoted(cells[0]) : NameSet{};
    if (directive.empty()) continue;
    ASSERT_EQ(directive.size(), 1u) << line;
    const std::string& d = *directive.begin();
    ASSERT_TRUE(registered.count(d)) << "unknown directive " << d;
    ++rows;
    for (const std::string& name : backquoted(cells[1]))
      EXPECT_FALSE(registered[d].count(name)) << d << " \"" << name << "\" is listed as unsupported but registered";
  }
  EXPECT_EQ(rows, registered.size() - 1) << "one row per directive except AreaLightSource";
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
