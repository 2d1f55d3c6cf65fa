// `eyetrace plugins --json` lists every registered plugin with its declared parameters, and
// `--markdown` prints one directive's table (the docs' tables are compared by docs_generated).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "scene/registry.h"

namespace eyetrace {
namespace {

std::string run(const std::string& args, int* status) {
  const std::string command = std::string(EYETRACE_BINARY_DIR "/bin/eyetrace ") + args + " 2>&1";
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int s = pclose(pipe);
  *status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  return out;
}

TEST(PluginsCommand, JsonListsEveryRegisteredPluginAndParameter) {
  int status = -1;
  const nlohmann::json all = nlohmann::json::parse(run("plugins --json", &status));
  ASSERT_EQ(status, 0);
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
  int status = -1;
  const std::string md = run("plugins --markdown Shape", &status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(md.find("| `sphere` | `float radius` 1 (scene units, (0, inf))"), std::string::npos) << md;
  run("plugins --markdown Nonsense", &status);
  EXPECT_EQ(status, 1);
}

}  // namespace
}  // namespace eyetrace
