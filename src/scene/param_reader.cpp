#include "scene/param_reader.h"

#include <cmath>
#include <filesystem>

#include "core/named_spectra.h"
#include "scene/spectrum_file.h"

namespace eyetrace {

namespace {

// Where `open` is, said from `at`: "2:31", or with its file when an Include lies between them.
std::string place_of(const Token& open, const Token& at) {
  if (open.file && open.file != at.file) return fmt::format("{}:{}:{}", open.file->name, open.line, open.column);
  return fmt::format("{}:{}", open.line, open.column);
}

enum class ValueKind { Numbers, Integers, Bools, Strings, Spectrum };

struct TypeKeyword {
  const char* name;
  ValueKind kind;
  size_t tuple;  // values per element: 3 for point3, 1 for float
};

// pbrt-v4's parameter types, plus the pbrt-v3 spellings it still reads.
constexpr TypeKeyword kParamTypes[] = {
    {"float", ValueKind::Numbers, 1},     {"integer", ValueKind::Integers, 1},  {"bool", ValueKind::Bools, 1},
    {"string", ValueKind::Strings, 1},    {"texture", ValueKind::Strings, 1},   {"point2", ValueKind::Numbers, 2},
    {"vector2", ValueKind::Numbers, 2},   {"point3", ValueKind::Numbers, 3},    {"vector3", ValueKind::Numbers, 3},
    {"normal", ValueKind::Numbers, 3},    {"normal3", ValueKind::Numbers, 3},   {"point", ValueKind::Numbers, 3},
    {"vector", ValueKind::Numbers, 3},    {"rgb", ValueKind::Numbers, 3},       {"color", ValueKind::Numbers, 3},
    {"spectrum", ValueKind::Spectrum, 1}, {"blackbody", ValueKind::Numbers, 1},
};

const TypeKeyword* find_type(const std::string& name) {
  for (const auto& t : kParamTypes)
    if (name == t.name) return &t;
  return nullptr;
}

std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) words.push_back(s.substr(start, i - start));
  }
  return words;
}

// Adds value tokens to one parameter, checking each against the declared type.
class ValueReader {
 public:
  ValueReader(Tokenizer& tok, Param& p, const TypeKeyword& type) : tok_(tok), p_(p), type_(type) {}

  // `open` is the '[' the value sits in, if any (for the missing-']' hint).
  void add(const Token& t, const Token* open) {
    if (t.kind == TokenKind::String) return add_string(t);
    if (t.text == "true" || t.text == "false") {
      if (type_.kind != ValueKind::Bools) fail(t, fmt::format("expected {}, got {}", expected(), t.text));
      p_.bools.push_back(t.text == "true");
      return;
    }
    if (type_.kind == ValueKind::Bools || type_.kind == ValueKind::Strings)
      fail(t, fmt::format("expected {}, got {}", expected(), t.describe()));
    if (type_.kind == ValueKind::Spectrum && !p_.strings.empty()) fail(t, "cannot mix numbers and a spectrum name");
    p_.numbers.push_back(number(t, open));
  }

  void check_counts() const {
    size_t n = p_.numbers.size() + p_.strings.size() + p_.bools.size();
    if (n == 0) eyetrace::fail(p_.loc, "parameter \"{}\" has no values", declaration());
    size_t nums = p_.numbers.size();
    if (type_.tuple > 1 && nums % type_.tuple != 0)
      eyetrace::fail(p_.loc, "parameter \"{}\" needs a multiple of {} values, got {}", declaration(), type_.tuple,
                     nums);
    if (type_.kind != ValueKind::Spectrum) return;
    if (nums > 1 && nums % 2 != 0)
      eyetrace::fail(p_.loc, "parameter \"{}\" needs one constant value or (wavelength, value) pairs, got {} values",
                     declaration(), nums);
    if (p_.strings.size() > 1)
      eyetrace::fail(p_.loc, "parameter \"{}\" takes one spectrum name or file name, got {}", declaration(),
                     p_.strings.size());
  }

 private:
  std::string declaration() const { return p_.type + " " + p_.name; }

  const char* expected() const {
    switch (type_.kind) {
      case ValueKind::Bools: return "true or false";
      case ValueKind::Strings: return "a quoted string";
      case ValueKind::Integers: return "an integer";
      case ValueKind::Spectrum: return "numbers or a quoted spectrum name";
      case ValueKind::Numbers: break;
    }
    return "a number";
  }

  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    eyetrace::fail(tok_.loc(t), "parameter \"{}\": {}", declaration(), message);
  }

  void add_string(const Token& t) {
    std::string s = t.string_value();
    switch (type_.kind) {
      case ValueKind::Bools:
        if (s != "true" && s != "false") fail(t, fmt::format("expected true or false, got {}", t.describe()));
        p_.bools.push_back(s == "true");
        return;
      case ValueKind::Spectrum:
        if (!p_.numbers.empty()) fail(t, "cannot mix numbers and a spectrum name");
        [[fallthrough]];
      case ValueKind::Strings: p_.strings.push_back(std::move(s)); return;
      default: fail(t, fmt::format("expected {}, got {}", expected(), t.describe()));
    }
  }

  double number(const Token& t, const Token* open) const {
    double v = 0;
    switch (parse_number(t.text, &v)) {
      case NumberStatus::Ok: break;
      case NumberStatus::NotANumber: {
        std::string hint;
        if (open) hint = fmt::format(" (is the ']' for the '[' at {} missing?)", place_of(*open, t));
        fail(t, fmt::format("expected {}, got {}{}", expected(), t.describe(), hint));
      }
      case NumberStatus::NotFinite: fail(t, fmt::format("{} is not a finite number", t.describe()));
      case NumberStatus::OutOfRange: fail(t, fmt::format("value {} is out of range", t.text));
    }
    if (type_.kind == ValueKind::Integers && (v != std::floor(v) || std::abs(v) > 2147483647.0))
      fail(t, fmt::format("value {} is not a 32-bit integer", t.text));
    return v;
  }

  Tokenizer& tok_;
  Param& p_;
  const TypeKeyword& type_;
};

Param declare(const Tokenizer& tok, const Token& decl) {
  std::string text = decl.string_value();
  std::vector<std::string> words = split_words(text);
  if (words.size() != 2) fail(tok.loc(decl), "malformed parameter declaration \"{}\": expected \"type name\"", text);
  if (!find_type(words[0])) {
    std::vector<std::string> names;
    for (const auto& t : kParamTypes) names.push_back(t.name);
    std::string hint = closest_match(words[0], names);
    fail(tok.loc(decl), "unknown parameter type \"{}\" in \"{}\"{}", words[0], text,
         hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint));
  }
  Param p;
  p.type = words[0];
  p.name = words[1];
  p.loc = tok.loc(decl);
  return p;
}

}  // namespace

// A spectrum named by a file ("spds/Au.eta.spd"): anything with a '.' or '/' that is not one
// of the named spectra. Its pairs replace the name. A file that is not there stays a name, its
// resolved path, for the plugin that reads it to report (scene/spectrum_param.h): the directive
// itself is not an error, so `eyetrace check` still checks the rest of it.
void read_spectrum_file_of(Param& p, const std::string& search_dir) {
  if (p.strings.size() != 1 || find_named_spectrum(p.strings[0])) return;
  const std::string& name = p.strings[0];
  if (name.find('.') == std::string::npos && name.find('/') == std::string::npos) return;
  const std::string path = spectrum_file_path(search_dir, name);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    p.strings[0] = path;
    return;
  }
  p.numbers = read_spectrum_file(search_dir, name, p.loc, p.name);
  p.strings.clear();
}

Param read_parameter(Tokenizer& tok, const Token& decl, const std::string& search_dir) {
  Param p = declare(tok, decl);
  ValueReader reader(tok, p, *find_type(p.type));
  Token v = tok.next();
  switch (v.kind) {
    case TokenKind::Word:
    case TokenKind::String: reader.add(v, nullptr); break;
    case TokenKind::OpenBracket:
      for (Token t = tok.next(); t.kind != TokenKind::CloseBracket; t = tok.next()) {
        if (t.kind == TokenKind::End)
          fail(tok.loc(v), "parameter \"{} {}\": '[' has no matching ']' before the end of the file", p.type, p.name);
        if (t.kind == TokenKind::OpenBracket)
          fail(tok.loc(t), "parameter \"{} {}\": unexpected '[' (is the ']' for the '[' at {} missing?)", p.type,
               p.name, place_of(v, t));
        reader.add(t, &v);
      }
      break;
    case TokenKind::CloseBracket:
      fail(tok.loc(v), "parameter \"{} {}\": unexpected ']' (no matching '[')", p.type, p.name);
    case TokenKind::End: fail(tok.loc(v), "parameter \"{} {}\" has no value: end of file", p.type, p.name);
  }
  reader.check_counts();
  if (p.canonical_type() == "spectrum") read_spectrum_file_of(p, search_dir);
  return p;
}

ParameterList read_parameter_list(Tokenizer& tok, const SourceLoc& directive_loc, const std::string& search_dir) {
  ParameterList list(directive_loc);
  while (tok.peek().kind == TokenKind::String) {
    Token decl = tok.next();
    list.add(read_parameter(tok, decl, search_dir));
  }
  return list;
}

}  // namespace eyetrace
