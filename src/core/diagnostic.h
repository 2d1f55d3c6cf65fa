// Diagnostics as values: one type carries every error and warning from the tokenizer, parser,
// parameter checks and plugin factories to the command line, with its place in the scene
// (file, line, column), the parameter it concerns, its severity and its message. Code that
// needs a diagnostic's parameter or message reads the field, never the formatted text.
#pragma once
#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace eyetrace {

struct SourceLoc {
  std::string file;  // empty for text given on the command line
  int line = 0;
  int column = 0;
  std::string to_string() const;  // "scene.pbrt:12:5" (or "<text>:1:3")
  bool known() const { return !file.empty() || line > 0; }
};

enum class Severity { Error, Warning };

// What an error is about, where the command line tells them apart: `eyetrace check` lists the
// files a scene names but that are not there (missing data) apart from the rest, and a warning
// about a deprecated form (Deprecated: read as written, nothing ignored) apart from warnings
// about what is ignored or approximated.
enum class DiagnosticKind { General, MissingFile, Deprecated };

struct Diagnostic {
  SourceLoc loc;
  std::string parameter;  // the scene parameter or command-line option it concerns, if any
  Severity severity = Severity::Error;
  std::string message;
  DiagnosticKind kind = DiagnosticKind::General;
  // "scene.pbrt:12:5: error: message"; without a place "error: message", or
  // "error: --option message" for a command-line option.
  std::string to_string() const;
  bool operator==(const Diagnostic& o) const;
};

// The errors of one run, collected so that a scene with several mistakes reports them all:
// each stage records what fails and carries on where later errors still mean something.
// Identical diagnostics are kept once. Beyond the limit (kMaxErrors unless
// set_diagnostic_limit() changed it) they are counted, not kept.
class DiagnosticList {
 public:
  static constexpr size_t kMaxErrors = 20;
  // Process-wide: `eyetrace check` lists every error (0: no limit), a render the first 20.
  static void set_limit(size_t max_kept);
  static size_t limit();
  void add(const Diagnostic& d);
  void add_all(const std::vector<Diagnostic>& ds);
  // Puts `other`'s diagnostics before the pos-th kept one, as if they had been added there:
  // the list becomes what adding the whole sequence in that order would have made (the same
  // kept ones, duplicates and count beyond the limit). Imports parsed on other threads join
  // the errors of the importing file this way, in statement order.
  void splice(size_t pos, const DiagnosticList& other);
  bool empty() const { return kept_.empty(); }
  const std::vector<Diagnostic>& kept() const { return kept_; }
  size_t suppressed() const { return suppressed_; }
  // Throws one SceneError holding every kept error (and a note of how many more there were).
  void throw_if_any() const;

 private:
  std::vector<Diagnostic> kept_;
  std::set<std::string> seen_;  // kept_ as text: a scene can have thousands of diagnostics
  size_t suppressed_ = 0;
};

}  // namespace eyetrace
