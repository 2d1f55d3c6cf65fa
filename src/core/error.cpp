#include "core/error.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <set>

namespace eyetrace {

std::string SourceLoc::to_string() const {
  std::string f = file.empty() ? "<text>" : file;
  if (line <= 0) return f;
  return fmt::format("{}:{}:{}", f, line, column);
}

void throw_error(const SourceLoc& loc, const std::string& message) {
  throw SceneError(fmt::format("{}: error: {}", loc.to_string(), message));
}

void throw_error(const std::string& message) { throw SceneError("error: " + message); }

namespace {
std::atomic<bool> g_warnings_enabled{true};
std::atomic<int> g_warning_count{0};
std::mutex g_warn_mutex;
}  // namespace

void set_warnings_enabled(bool enabled) { g_warnings_enabled = enabled; }
int warning_count() { return g_warning_count; }

void warn(const SourceLoc& loc, const std::string& message) {
  std::string text = fmt::format("{}: warning: {}", loc.to_string(), message);
  std::lock_guard<std::mutex> lock(g_warn_mutex);
  static std::set<std::string> seen;
  if (!seen.insert(text).second) return;
  ++g_warning_count;
  if (g_warnings_enabled) std::fprintf(stderr, "%s\n", text.c_str());
}

static size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + size_t(a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

}  // namespace eyetrace
