// The shared parts of the tests that keep the generated tables of docs/eye-models.md honest
// (tests/optics/docs_tables_test.cpp, chromatic_docs_test.cpp): the presets in the order the
// tables list them, a row's label, and the check that a freshly computed table stands in the doc
// (on a mismatch it prints the fresh table, to paste over the old one).
#pragma once
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "optics/eye_models.h"

namespace eyetrace::optics::test {

struct EyePreset {
  const char* model;
  const char* variant;
};
inline constexpr EyePreset kDocPresets[] = {{"gullstrand", ""}, {"legrand", ""},       {"kooijman", ""},
                                            {"navarro", ""},    {"navarro", "wu2011"}, {"escudero-sanz", ""},
                                            {"arizona", ""}};

// The preset's relaxed eye.
inline Prescription make_preset_eye(const EyePreset& preset) {
  EyeOptions o;
  o.model = preset.model;
  o.variant = preset.variant;
  return make_eye(o);
}

// "navarro", "navarro wu2011": the first column of the tables.
inline std::string preset_label(const EyePreset& preset) {
  return std::string(preset.model) + (*preset.variant ? std::string(" ") + preset.variant : "");
}

inline testing::AssertionResult table_is_in_eye_models_doc(const std::string& table) {
  std::ifstream in(std::string(EYETRACE_SOURCE_DIR) + "/docs/eye-models.md");
  std::ostringstream doc;
  doc << in.rdbuf();
  if (doc.str().find(table) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "docs/eye-models.md is stale; fresh table:\n" << table;
}

}  // namespace eyetrace::optics::test
