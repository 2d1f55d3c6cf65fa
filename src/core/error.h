// Errors and warnings that point at the scene file, like a compiler: file:line:col. Both are
// Diagnostic values (core/diagnostic.h); an error travels as a SceneError holding them.
#pragma once
#include <fmt/core.h>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace eyetrace {

// Every user-facing failure (bad scene, bad option, unreadable file) is a SceneError holding
// one or more error diagnostics; what() is their text, one per line ("scene.pbrt:12:5: error:
// ..."); main() prints it and exits non-zero.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(Diagnostic d);
  explicit SceneError(std::vector<Diagnostic> ds);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  // The first (often the only) diagnostic.
  const Diagnostic& first() const { return diagnostics_.front(); }

 private:
  std::vector<Diagnostic> diagnostics_;
};

[[noreturn]] void throw_error(const SourceLoc& loc, const std::string& message);
[[noreturn]] void throw_error(const std::string& message);
// An error about one scene parameter or command-line option: `parameter` is kept as a field.
[[noreturn]] void throw_parameter_error(const SourceLoc& loc, const std::string& parameter, const std::string& message);
// An error about a file the scene names that is not there (DiagnosticKind::MissingFile).
[[noreturn]] void throw_missing_file(const SourceLoc& loc, const std::string& parameter, const std::string& message);
// Warnings go to stderr (once per distinct text) unless warnings are silenced by --quiet.
// With strict warnings (--strict) a warning is thrown as an error instead.
void warn(const SourceLoc& loc, const std::string& message);
// A warning about a deprecated form that is read as written (DiagnosticKind::Deprecated): shown
// as a warning, but nothing is ignored, so neither --strict nor `eyetrace check` fails on it.
void warn_deprecated(const SourceLoc& loc, const std::string& message);
void set_warnings_enabled(bool enabled);
void set_warnings_fatal(bool fatal);
int warning_count();

// While alive, every warning (from any thread) is collected here instead of printed, and is
// never fatal: `eyetrace check` lists them all with the errors. Identical ones are kept once.
class WarningCollector {
 public:
  WarningCollector();
  ~WarningCollector();
  WarningCollector(const WarningCollector&) = delete;
  WarningCollector& operator=(const WarningCollector&) = delete;
  std::vector<Diagnostic> warnings() const;

 private:
  friend void deliver_warning(const Diagnostic& d);
  DiagnosticList list_;
  WarningCollector* outer_;
};

template <typename... Args>
[[noreturn]] void fail(const SourceLoc& loc, fmt::format_string<Args...> f, Args&&... args) {
  throw_error(loc, fmt::format(f, std::forward<Args>(args)...));
}

// While alive, the warnings of this thread are appended to *into, in order, instead of being
// delivered (a fatal one still throws at once); deliver_warnings() delivers them later as warn()
// would have. The parser keeps the warnings of Imports parsed on other threads this way, to
// deliver them in statement order. Captures nest (the innermost wins) and are per thread.
class WarningCapture {
 public:
  explicit WarningCapture(std::vector<Diagnostic>* into);
  ~WarningCapture();
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;

 private:
  std::vector<Diagnostic>* outer_;
};
void deliver_warnings(const std::vector<Diagnostic>& warnings);

// "did you mean" helper: the closest candidate by edit distance, or "" if none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace eyetrace
