// Entry points of the pbrt-v4 parser: reads files whole (Include/Import textually, with
// recursion and depth checks), runs the directive loop, and checks what must be closed at
// the end. The directives themselves are in scene_parser.cpp.
#include "scene/parser.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/gzip.h"
#include "scene/param_reader.h"
#include "scene/scene_parser.h"

namespace eyetrace {
namespace parsing {

namespace {

std::optional<std::string> read_whole_file(const fs::path& path, std::string* error) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    *error = "it is a directory";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    *error = std::strerror(errno);
    return std::nullopt;
  }
  // One read of the whole file: meshes with millions of numbers are the common large case.
  std::streamoff size = in.tellg();
  if (size < 0) {
    *error = "cannot determine its size";
    return std::nullopt;
  }
  std::string text(size_t(size), '\0');
  in.seekg(0);
  if (!in.read(text.data(), std::streamsize(text.size()))) {
    *error = "read error";
    return std::nullopt;
  }
  return text;
}

}  // namespace

SceneParser::SceneParser(fs::path search_dir, const ParseOptions& options) : options_(options) {
  desc_.search_dir = search_dir.string();
  desc_.camera.name = "perspective";
  // pbrt-v4 starts with one anonymous diffuse material so shapes before any Material have one.
  desc_.materials.push_back(SceneEntity{"diffuse", ParameterList(SourceLoc{}), SourceLoc{}});
}

// ---------------------------------------------------------------------------------------
// Files and the directive loop

// The whole text of a scene file, inflated when it is gzip-compressed (pbrt-v4 scenes ship
// their large geometry as .pbrt.gz); errors name the file, and the Include that named it.
std::string SceneParser::read_scene_text(const fs::path& path, const SourceLoc* included_from) {
  std::string error;
  std::optional<std::string> text = read_whole_file(path, &error);
  if (text && is_gzip(*text)) {
    text = gunzip(*text, &error);
    if (!text) error = fmt::format("gzip-compressed file: {}", error);
  }
  if (text) return std::move(*text);
  std::string message = fmt::format("cannot read scene file \"{}\": {}", path.string(), error);
  std::error_code exists_ec;
  if (!fs::exists(path, exists_ec)) throw_missing_file(included_from ? *included_from : SourceLoc{}, "", message);
  if (included_from) throw_error(*included_from, message);
  throw_error(message);
}

TokenFile SceneParser::token_file(const fs::path& path) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(path, ec);
  if (ec) canonical = fs::absolute(path);
  return TokenFile{path.string(), canonical.string(), path.parent_path().string()};
}

// The top-level parser holds its warnings back too (sync() delivers them), so that those of
// the Imports it merges later take their places among them.
void SceneParser::parse_file(const fs::path& path) {
  Tokenizer tok(read_scene_text(path, nullptr), token_file(path));
  WarningCapture capture(&warnings_);
  run(tok);
}

void SceneParser::parse_text(std::string text, const std::string& filename) {
  std::error_code ec;
  fs::path as_file = fs::weakly_canonical(fs::path(desc_.search_dir) / filename, ec);
  Tokenizer tok(std::move(text), TokenFile{filename, as_file.string(), desc_.search_dir});
  WarningCapture capture(&warnings_);
  run(tok);
}

// A directive that fails is recorded and the parse goes on at the next directive keyword, so
// one run reports every independent mistake (up to DiagnosticList::kMaxErrors).
void SceneParser::run(Tokenizer& tok) {
  for (;;) {
    try {
      tok.release_finished();  // no token is held between directives
      Token t = tok.next();
      if (t.kind == TokenKind::End) return;
      SourceLoc loc = tok.loc(t);
      if (t.kind != TokenKind::Word)
        fail(loc, "unexpected {} where a directive (Shape, AttributeBegin, ...) was expected", t.describe());
      auto it = handlers().find(t.text);
      if (it == handlers().end()) unknown_directive(t, loc);
      if (!pending_.empty() && needs_imports_merged(t.text)) sync();
      (this->*(it->second))(tok, loc);
    } catch (const SceneError& e) {
      errors_.add_all(e.diagnostics());
      if (tok.took_end()) {  // the failed directive ran to the end of the text
        cut_short_ = true;
        return;
      }
      if (!skip_to_directive(tok)) return;
    }
  }
}

// A bare word that is neither a number nor a bool can only be a directive (perhaps a
// misspelt one, which then gets its own error).
static bool starts_directive(const Token& t) {
  double v;
  return t.kind == TokenKind::Word && t.text != "true" && t.text != "false" &&
         parse_number(t.text, &v) == NumberStatus::NotANumber;
}

// Skips what is left of a failed directive (its parameters, values, brackets) up to the next
// directive keyword. False at the end of the text, or when the text cannot be read on (an
// unterminated string: the parse is then cut short, since what follows would only produce
// errors that are not the author's).
bool SceneParser::skip_to_directive(Tokenizer& tok) {
  try {
    for (Token t = tok.peek(); t.kind != TokenKind::End; t = tok.peek()) {
      if (starts_directive(t)) return true;
      tok.next();
    }
  } catch (const SceneError&) {
    cut_short_ = true;
  }
  return false;
}

void SceneParser::unknown_directive(const Token& t, const SourceLoc& loc) const {
  double v;
  if (parse_number(t.text, &v) != NumberStatus::NotANumber)
    fail(loc, "unexpected number {} where a directive was expected (a list of several values needs [ ])", t.text);
  fail(loc, "unknown directive \"{}\"{}", t.text, hint_suffix(std::string(t.text), keys_of(handlers())));
}

SceneDescription SceneParser::finish(const std::string& top_file) {
  sync();
  check_end(top_file);
  errors_.throw_if_any();
  return std::move(desc_);
}

ParsedScene SceneParser::finish_collecting(const std::string& top_file) {
  sync();
  check_end(top_file);
  ParsedScene r;
  r.errors = errors_.kept();
  r.buildable = !cut_short_ && !import_cut_short_ && in_world_;
  r.desc = std::move(desc_);
  return r;
}

void SceneParser::check_end(const std::string& top_file) {
  // A text cut short by an error has not really ended: its open blocks and missing WorldBegin
  // follow from that error and are not reported again.
  if (cut_short_) return;
  if (!blocks_.empty()) {
    const OpenBlock& b = blocks_.back();
    const char* closer = b.directive == "ObjectBegin"      ? "ObjectEnd"
                         : b.directive == "TransformBegin" ? "TransformEnd"
                                                           : "AttributeEnd";
    errors_.add(Diagnostic{b.loc, "", Severity::Error,
                           fmt::format("{} has no matching {} before the end of the scene", b.directive, closer)});
  }
  if (!in_world_)
    errors_.add(Diagnostic{SourceLoc{top_file, 0, 0}, "", Severity::Error, "the scene ends before WorldBegin"});
}

fs::path SceneParser::resolve_include(const std::string& name, const SourceLoc& loc, const char* directive,
                                      const fs::path& dir) const {
  fs::path p(name);
  std::vector<fs::path> candidates;
  if (p.is_absolute()) {
    candidates.push_back(p);
  } else {
    candidates.push_back((dir / p).lexically_normal());
    fs::path in_search = (fs::path(desc_.search_dir) / p).lexically_normal();
    std::error_code ec;
    if (fs::absolute(candidates[0], ec).lexically_normal() != in_search) candidates.push_back(in_search);
  }
  std::string looked;
  for (const auto& c : candidates) {
    std::error_code ec;
    if (fs::exists(c, ec)) return c;
    looked += (looked.empty() ? "" : ", ") + fmt::format("\"{}\"", c.string());
  }
  throw_missing_file(loc, "", fmt::format("{} \"{}\": file not found (looked for {})", directive, name, looked));
}

// The files open around an Include or Import are those of this parser's tokenizer, after the
// files that imported this one (each Import has a parser of its own).
fs::path SceneParser::included_file(Tokenizer& tok, const SourceLoc& loc, const char* directive) {
  std::string name = read_name(tok, directive, "file name");
  fs::path path = resolve_include(name, loc, directive, tok.current_file().dir);
  const std::string canonical = token_file(path).canonical;
  std::vector<std::string> open = ancestors_;
  for (const TokenFile* f : tok.open_files()) open.push_back(f->canonical);
  for (size_t i = 0; i < open.size(); ++i) {
    if (open[i] != canonical) continue;
    std::string chain;
    for (size_t j = i; j < open.size(); ++j) chain += fs::path(open[j]).filename().string() + " -> ";
    fail(loc, "recursive {} of \"{}\" ({}{})", directive, path.string(), chain,
         fs::path(canonical).filename().string());
  }
  if (open.size() >= kMaxIncludeDepth) fail(loc, "Include nesting is deeper than {} files", kMaxIncludeDepth);
  return path;
}

// As pbrt-v4, the included file's tokens are spliced in where the Include stands: a directive
// begun in it may end after it, and one begun before it may take its parameters from it.
void SceneParser::include(Tokenizer& tok, const SourceLoc& loc) {
  fs::path path = included_file(tok, loc, "Include");
  tok.include(read_scene_text(path, &loc), token_file(path));
}

// ---------------------------------------------------------------------------------------
// Reading helpers

std::string SceneParser::read_name(Tokenizer& tok, const char* directive, const char* what, SourceLoc* at) {
  Token t = tok.next();
  if (t.kind != TokenKind::String) fail(tok.loc(t), "{}: expected a quoted {}, got {}", directive, what, t.describe());
  if (at) *at = tok.loc(t);
  return t.string_value();
}

std::vector<float> SceneParser::read_numbers(Tokenizer& tok, const char* directive, size_t count) {
  std::vector<float> v;
  while (v.size() < count) {
    // Peeked, not taken, until it is a number: a directive that follows too few numbers is
    // left for the parse to go on with.
    Token t = tok.peek();
    double x = 0;
    NumberStatus status = t.kind == TokenKind::Word ? parse_number(t.text, &x) : NumberStatus::NotANumber;
    if (status == NumberStatus::Ok && std::abs(x) > 3.0e38) status = NumberStatus::OutOfRange;
    if (status == NumberStatus::NotANumber)
      fail(tok.loc(t), "{} takes {} numbers; got {} after {}", directive, count, t.describe(), v.size());
    if (status == NumberStatus::NotFinite) fail(tok.loc(t), "{}: {} is not a finite number", directive, t.describe());
    if (status == NumberStatus::OutOfRange) fail(tok.loc(t), "{}: value {} is out of range", directive, t.text);
    tok.next();
    v.push_back(float(x));
  }
  return v;
}

SceneEntity SceneParser::read_entity(Tokenizer& tok, const SourceLoc& loc, const char* directive) {
  SceneEntity e;
  e.name = read_name(tok, directive, "type name");
  e.params = read_parameter_list(tok, loc, desc_.search_dir);
  e.loc = loc;
  return e;
}

}  // namespace parsing

using parsing::SceneParser;
namespace fs = std::filesystem;

namespace {

fs::path absolute_dir(const std::string& dir) {
  std::error_code ec;
  fs::path p = dir.empty() ? fs::current_path(ec) : fs::absolute(dir, ec);
  return p.lexically_normal();
}

}  // namespace

SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options) {
  std::error_code ec;
  fs::path abs = fs::absolute(path, ec);
  SceneParser parser(abs.parent_path().lexically_normal(), options);
  parser.parse_file(path);
  return parser.finish(path);
}

ParsedScene parse_scene_file_collecting(const std::string& path, const ParseOptions& options) {
  std::error_code ec;
  fs::path abs = fs::absolute(path, ec);
  SceneParser parser(abs.parent_path().lexically_normal(), options);
  try {
    parser.parse_file(path);
  } catch (const SceneError& e) {  // the top file itself cannot be read
    return ParsedScene{SceneDescription{}, e.diagnostics(), false};
  }
  return parser.finish_collecting(path);
}

SceneDescription parse_scene_string(std::string_view text, const std::string& filename, const std::string& search_dir) {
  SceneParser parser(absolute_dir(search_dir), ParseOptions{});
  parser.parse_text(std::string(text), filename);
  return parser.finish(filename);
}

SceneEntity parse_directive_text(std::string_view text, const std::string& directive, const std::string& origin) {
  Tokenizer tok(std::string(text), origin);
  Token first = tok.peek();
  SourceLoc loc = tok.loc(first);
  // The keyword may be left out: `--camera '"thinlens" "float lensradius" 0.01'`.
  if (first.kind == TokenKind::Word) {
    if (first.text != directive) fail(loc, "expected a {} directive, got {}", directive, first.describe());
    tok.next();
  }
  SceneEntity e;
  Token name = tok.next();
  if (name.kind != TokenKind::String)
    fail(tok.loc(name), "{}: expected a quoted type name, got {}", directive, name.describe());
  e.name = name.string_value();
  e.params = read_parameter_list(tok, loc);
  e.loc = loc;
  Token rest = tok.next();
  if (rest.kind != TokenKind::End)
    fail(tok.loc(rest), "{}: unexpected {} after the parameters", directive, rest.describe());
  return e;
}

}  // namespace eyetrace
