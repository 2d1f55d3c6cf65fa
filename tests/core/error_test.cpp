// DiagnosticList::splice and WarningCapture, which put the errors and warnings of Imports
// parsed on other threads in statement order: checked against the plain sequence added in
// that order (DiagnosticList::add), the definition splice has to meet.
#include <gtest/gtest.h>

#include <random>

#include "../support/unity_id.h"
#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Diagnostic error_at(int line) { return Diagnostic{SourceLoc{"f.pbrt", line, 1}, "", Severity::Error, "e"}; }

std::vector<std::string> texts(const DiagnosticList& l) {
  std::vector<std::string> out;
  for (const Diagnostic& d : l.kept()) out.push_back(d.to_string());
  return out;
}

class LimitGuard {
 public:
  explicit LimitGuard(size_t limit) : old_(DiagnosticList::limit()) { DiagnosticList::set_limit(limit); }
  ~LimitGuard() { DiagnosticList::set_limit(old_); }

 private:
  size_t old_;
};

// Random sequences with repeats (lines drawn from a few values), cut in three: the middle
// spliced into the outer two must give the list of the whole sequence, kept and counted.
TEST(DiagnosticListSplice, EqualsAddingTheWholeSequenceInOrder) {
  std::mt19937 rng(7);
  for (size_t limit : {size_t(0), size_t(1), size_t(4), size_t(20)}) {
    LimitGuard guard(limit);
    for (int trial = 0; trial < 300; ++trial) {
      std::uniform_int_distribution<int> length(0, 12), line(1, 9);
      std::vector<Diagnostic> a(size_t(length(rng))), b(size_t(length(rng))), c(size_t(length(rng)));
      for (auto* part : {&a, &b, &c})
        for (Diagnostic& d : *part) d = error_at(line(rng));
      DiagnosticList whole, outer, middle;
      for (auto* part : {&a, &b, &c}) whole.add_all(*part);
      outer.add_all(a);
      const size_t at = outer.kept().size();
      outer.add_all(c);
      middle.add_all(b);
      outer.splice(at, middle);
      ASSERT_EQ(texts(outer), texts(whole)) << "limit " << limit << " trial " << trial;
      ASSERT_EQ(outer.suppressed(), whole.suppressed()) << "limit " << limit << " trial " << trial;
    }
  }
}

TEST(WarningCapture, HoldsWarningsInOrderUntilDelivered) {
  std::vector<Diagnostic> held;
  WarningCollector collector;
  {
    WarningCapture capture(&held);
    warn(SourceLoc{"f.pbrt", 2, 1}, "second");
    warn(SourceLoc{"f.pbrt", 1, 1}, "first");
  }
  EXPECT_TRUE(collector.warnings().empty());
  ASSERT_EQ(held.size(), 2u);
  deliver_warnings(held);
  ASSERT_EQ(collector.warnings().size(), 2u);
  EXPECT_EQ(collector.warnings()[0].message, "second");
  EXPECT_EQ(collector.warnings()[1].message, "first");
}

// With --strict a warning is an error where it is raised, captured or not.
TEST(WarningCapture, FatalWarningsStillThrow) {
  std::vector<Diagnostic> held;
  set_warnings_fatal(true);
  bool threw = false;
  {
    WarningCapture capture(&held);
    try {
      warn(SourceLoc{"f.pbrt", 3, 1}, "strict");
    } catch (const SceneError& e) {
      threw = true;
      EXPECT_EQ(e.first().loc.line, 3);
    }
  }
  set_warnings_fatal(false);
  EXPECT_TRUE(threw);
  EXPECT_TRUE(held.empty());
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
