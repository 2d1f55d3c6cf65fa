// Parser for pbrt-v4's scene text format. Errors are SceneErrors that name file:line:col
// and the offending token or parameter; unknown directives are errors, never skipped.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "scene/scene_description.h"

namespace eyetrace {

struct ParseOptions {
  // An Import of a file at least this large (bytes on disk) is parsed on a task of its own, in
  // parallel with the rest, as pbrt-v4 does; a smaller one in place. Either way the result is
  // the same. 0: every Import on a task; the largest value: none.
  std::uintmax_t import_task_min_bytes = kDefaultImportTaskMinBytes;
  static constexpr std::uintmax_t kDefaultImportTaskMinBytes = 256 * 1024;
};

// Reads a scene file (and everything it Includes/Imports).
SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options = {});

// For `eyetrace check`: what parsed, and every error instead of a thrown SceneError. Directives
// that failed are left out of `desc`; `buildable` is false when the rest cannot be built on
// (the file cannot be read, an error cut the text short, or it has no WorldBegin).
struct ParsedScene {
  SceneDescription desc;
  std::vector<Diagnostic> errors;
  bool buildable = true;
};
ParsedScene parse_scene_file_collecting(const std::string& path, const ParseOptions& options = {});

// Parses scene text held in memory; `filename` is used in messages, `search_dir` resolves
// Include/Import and relative paths.
SceneDescription parse_scene_string(std::string_view text, const std::string& filename, const std::string& search_dir);

// Parses one directive given on the command line, e.g.
//   Camera "thinlens" "float lensradius" 0.0025 "float focaldistance" 1.5
// `directive` is the expected directive keyword ("Camera", "Film", "Sampler", ...); its
// name and parameters are returned (messages refer to `origin`, e.g. "--camera").
SceneEntity parse_directive_text(std::string_view text, const std::string& directive, const std::string& origin);

}  // namespace eyetrace
