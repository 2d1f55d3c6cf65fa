// Reads pbrt-v4 parameter lists ("float radius" 1, "rgb reflectance" [.5 .5 .5], ...) from a
// token stream into typed Params. Value kinds are checked here, where the offending token's
// line and column are still known; value meaning is left to the plugin that reads them.
#pragma once
#include "scene/params.h"
#include "scene/tokenizer.h"

namespace eyetrace {

// Reads the value(s) following the declaration token `decl` ("type name"). A "spectrum" given
// as a file name (not a named spectrum) is read here, as pbrt-v4 does, relative to
// `search_dir` (scene/spectrum_file.h), and kept as its (wavelength, value) pairs.
Param read_parameter(Tokenizer& tok, const Token& decl, const std::string& search_dir = "");

// Reads parameters while the next token is a quoted string; stops before anything else.
ParameterList read_parameter_list(Tokenizer& tok, const SourceLoc& directive_loc, const std::string& search_dir = "");

}  // namespace eyetrace
