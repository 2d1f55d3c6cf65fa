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

std::string Diagnostic::to_string() const {
  const char* kind = severity == Severity::Error ? "error" : "warning";
  // A command-line option has no place in a file: its name leads the message instead.
  if (!loc.known() && !parameter.empty() && parameter[0] == '-')
    return fmt::format("{}: {} {}", kind, parameter, message);
  if (!loc.known()) return fmt::format("{}: {}", kind, message);
  return fmt::format("{}: {}: {}", loc.to_string(), kind, message);
}

bool Diagnostic::operator==(const Diagnostic& o) const {
  return loc.file == o.loc.file && loc.line == o.loc.line && loc.column == o.loc.column && parameter == o.parameter &&
         severity == o.severity && message == o.message && kind == o.kind;
}

namespace {
std::atomic<size_t> g_diagnostic_limit{DiagnosticList::kMaxErrors};

// Everything operator== compares, as one string.
std::string identity_of(const Diagnostic& d) {
  return fmt::format("{}\x1f{}\x1f{}\x1f{}\x1f{}", d.to_string(), d.loc.file, d.parameter, int(d.kind),
                     int(d.severity));
}
}  // namespace

void DiagnosticList::set_limit(size_t max_kept) { g_diagnostic_limit = max_kept; }
size_t DiagnosticList::limit() { return g_diagnostic_limit; }

void DiagnosticList::add(const Diagnostic& d) {
  if (!seen_.insert(identity_of(d)).second) return;
  const size_t max_kept = limit();
  if (max_kept == 0 || kept_.size() < max_kept)
    kept_.push_back(d);
  else
    ++suppressed_;
}

void DiagnosticList::add_all(const std::vector<Diagnostic>& ds) {
  for (const Diagnostic& d : ds) add(d);
}

void DiagnosticList::splice(size_t pos, const DiagnosticList& other) {
  // Every diagnostic a list did not keep came after `limit` distinct ones of that list, so it
  // comes after as many in the spliced sequence too: the kept ones are all that can be kept.
  std::vector<Diagnostic> sequence(kept_.begin(), kept_.begin() + std::ptrdiff_t(std::min(pos, kept_.size())));
  sequence.insert(sequence.end(), other.kept_.begin(), other.kept_.end());
  sequence.insert(sequence.end(), kept_.begin() + std::ptrdiff_t(std::min(pos, kept_.size())), kept_.end());
  std::set<std::string> seen = std::move(seen_);
  seen.insert(other.seen_.begin(), other.seen_.end());
  kept_.clear();
  seen_.clear();
  add_all(sequence);
  seen_ = std::move(seen);
  suppressed_ = seen_.size() - kept_.size();  // every distinct one is either kept or counted
}

void DiagnosticList::throw_if_any() const {
  if (kept_.empty()) return;
  std::vector<Diagnostic> all = kept_;
  if (suppressed_ > 0)
    all.push_back(Diagnostic{{},
                             "",
                             Severity::Error,
                             fmt::format("{} more error{} not shown (at most {} are listed)", suppressed_,
                                         suppressed_ == 1 ? "" : "s", limit())});
  throw SceneError(std::move(all));
}

namespace {
std::string join_lines(const std::vector<Diagnostic>& ds) {
  std::string text;
  for (const Diagnostic& d : ds) text += (text.empty() ? "" : "\n") + d.to_string();
  return text;
}
}  // namespace

SceneError::SceneError(Diagnostic d) : SceneError(std::vector<Diagnostic>{std::move(d)}) {}
SceneError::SceneError(std::vector<Diagnostic> ds) : std::runtime_error(join_lines(ds)), diagnostics_(std::move(ds)) {}

void throw_error(const SourceLoc& loc, const std::string& message) {
  throw SceneError(Diagnostic{loc, "", Severity::Error, message});
}

void throw_error(const std::string& message) { throw SceneError(Diagnostic{{}, "", Severity::Error, message}); }

void throw_parameter_error(const SourceLoc& loc, const std::string& parameter, const std::string& message) {
  throw SceneError(Diagnostic{loc, parameter, Severity::Error, message});
}

void throw_missing_file(const SourceLoc& loc, const std::string& parameter, const std::string& message) {
  throw SceneError(Diagnostic{loc, parameter, Severity::Error, message, DiagnosticKind::MissingFile});
}

namespace {
WarningCollector* g_collector = nullptr;  // guarded by g_warn_mutex
std::atomic<bool> g_warnings_enabled{true};
std::atomic<bool> g_warnings_fatal{false};
std::atomic<int> g_warning_count{0};
std::mutex g_warn_mutex;
}  // namespace

void set_warnings_enabled(bool enabled) { g_warnings_enabled = enabled; }
void set_warnings_fatal(bool fatal) { g_warnings_fatal = fatal; }
int warning_count() { return g_warning_count; }

WarningCollector::WarningCollector() {
  std::lock_guard<std::mutex> lock(g_warn_mutex);
  outer_ = g_collector;
  g_collector = this;
}

WarningCollector::~WarningCollector() {
  std::lock_guard<std::mutex> lock(g_warn_mutex);
  g_collector = outer_;
}

std::vector<Diagnostic> WarningCollector::warnings() const {
  std::lock_guard<std::mutex> lock(g_warn_mutex);
  return list_.kept();
}

namespace {
thread_local std::vector<Diagnostic>* t_capture = nullptr;
}  // namespace

// A warning that is not fatal: to the collector, or printed once.
void deliver_warning(const Diagnostic& d) {
  std::lock_guard<std::mutex> lock(g_warn_mutex);
  if (g_collector) {
    g_collector->list_.add(d);
    return;
  }
  static std::set<std::string> seen;
  std::string text = d.to_string();
  if (!seen.insert(text).second) return;
  ++g_warning_count;
  if (g_warnings_enabled) std::fprintf(stderr, "%s\n", text.c_str());
}

WarningCapture::WarningCapture(std::vector<Diagnostic>* into) : outer_(t_capture) { t_capture = into; }
WarningCapture::~WarningCapture() { t_capture = outer_; }

namespace {
// To this thread's WarningCapture if one is alive, else delivered now.
void hold_or_deliver(Diagnostic d) {
  if (t_capture)
    t_capture->push_back(std::move(d));
  else
    deliver_warning(d);
}
}  // namespace

void deliver_warnings(const std::vector<Diagnostic>& warnings) {
  for (const Diagnostic& d : warnings) deliver_warning(d);
}

void warn(const SourceLoc& loc, const std::string& message) {
  bool collecting;
  {
    std::lock_guard<std::mutex> lock(g_warn_mutex);
    collecting = g_collector != nullptr;
  }
  if (!collecting && g_warnings_fatal)
    throw SceneError(Diagnostic{loc, "", Severity::Error, message + " (a warning, fatal with --strict)"});
  hold_or_deliver(Diagnostic{loc, "", Severity::Warning, message});
}

void warn_deprecated(const SourceLoc& loc, const std::string& message) {
  hold_or_deliver(Diagnostic{loc, "", Severity::Warning, message, DiagnosticKind::Deprecated});
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
