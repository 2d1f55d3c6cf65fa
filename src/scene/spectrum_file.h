// Spectrum files, as pbrt-v4 reads them ("spectrum eta" "spds/Au.eta.spd"): text of
// (wavelength nm, value) pairs separated by white space or commas, with # comments to the end
// of a line. pbrt-v4 resolves the name against the search directory (the top-level scene
// file's directory), as plugins resolve theirs.
#pragma once
#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace eyetrace {

// Where the file `name` is looked for: relative to `search_dir` unless absolute.
std::string spectrum_file_path(const std::string& search_dir, const std::string& name);

// The pairs of the file `name` (relative to `search_dir` unless absolute), interleaved, checked:
// an even count of finite numbers, at least two pairs, increasing positive wavelengths. Errors
// are at `at` and name the parameter and the file (with its line for a bad value); a file
// that is not there is DiagnosticKind::MissingFile (the parser does not call this for one: it
// leaves its path in the parameter, scene/param_reader.cpp).
std::vector<double> read_spectrum_file(const std::string& search_dir, const std::string& name, const SourceLoc& at,
                                       const std::string& parameter);

}  // namespace eyetrace
