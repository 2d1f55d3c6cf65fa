// Errors and warnings that point at the scene file, like a compiler: file:line:col.
#pragma once
#include <fmt/core.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace eyetrace {

struct SourceLoc {
  std::string file;  // empty for text given on the command line
  int line = 0;
  int column = 0;
  std::string to_string() const;  // "scene.pbrt:12:5" (or "<camera>:1:3")
};

// Every user-facing failure (bad scene, bad option, unreadable file) is a SceneError whose
// message is complete ("scene.pbrt:12:5: error: ..."); main() prints it and exits non-zero.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void throw_error(const SourceLoc& loc, const std::string& message);
[[noreturn]] void throw_error(const std::string& message);
// Warnings go to stderr (once per distinct text) unless warnings are silenced by --quiet.
void warn(const SourceLoc& loc, const std::string& message);
void set_warnings_enabled(bool enabled);
int warning_count();

template <typename... Args>
[[noreturn]] void fail(const SourceLoc& loc, fmt::format_string<Args...> f, Args&&... args) {
  throw_error(loc, fmt::format(f, std::forward<Args>(args)...));
}

// "did you mean" helper: the closest candidate by edit distance, or "" if none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace eyetrace
