// `eyetrace plugins --json` lists every registered plugin with its declared parameters, and
// `--markdown` prints one directive's table (the docs' tables are compared by docs_generated).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "../support/eyetrace_process.h"
#include "../support/unity_id.h"
#include "scene/registry.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::run_eyetrace;

TEST(PluginsCommand, JsonListsEveryRegisteredPluginAndParameter) {
  const test::RunResult run = run_eyetrace("plugins --json");
  ASSERT_EQ(run.status, 0);
  const nlohmann::json all = nlohmann::json::parse(run.output);
  std::set<std::string> listed;
  size_t params = 0;
  for (const auto& g : all) {
    for (const auto& n : g["names"]) listed.insert(g["directive"].get<std::string>() + " " + n.get<std::string>());
    params += g["parameters"].size();
  }
  for (const PluginListing& p : Registry::builtin().listing())
    EXPECT_TRUE(listed.count(p.spec->directive + " " + p.name)) << p.spec->directive << " " << p.name;
  EXPECT_GT(params, 100u);
}

TEST(PluginsCommand, MarkdownOfADirectiveAndErrors) {
  const test::RunResult md = run_eyetrace("plugins --markdown Shape");
  EXPECT_EQ(md.status, 0);
  EXPECT_NE(md.output.find("| `sphere` | `float radius` 1 (scene units, (0, inf))"), std::string::npos) << md.output;
  EXPECT_EQ(run_eyetrace("plugins --markdown Nonsense").status, 1);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
