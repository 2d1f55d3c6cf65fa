#include "scene/tokenizer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace eyetrace {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\n'; }

// A bare word ends at whitespace, a quote, a bracket or a comment.
bool ends_word(char c) { return is_space(c) || c == '"' || c == '[' || c == ']' || c == '#'; }

bool is_known_escape(char c) {
  switch (c) {
    case 'b':
    case 'f':
    case 'n':
    case 'r':
    case 't':
    case '\\':
    case '\'':
    case '"': return true;
    default: return false;
  }
}

char decode_escape(char c) {
  switch (c) {
    case 'b': return '\b';
    case 'f': return '\f';
    case 'n': return '\n';
    case 'r': return '\r';
    case 't': return '\t';
    default: return c;  // \\ \' \"
  }
}

// Long tokens (a mangled file) are cut so the message stays one readable line.
std::string excerpt(std::string_view s) {
  constexpr size_t kMax = 40;
  return s.size() <= kMax ? std::string(s) : std::string(s.substr(0, kMax)) + "...";
}

}  // namespace

std::string Token::string_value() const {
  if (!has_escapes) return std::string(text);
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size())
      out.push_back(decode_escape(text[++i]));
    else
      out.push_back(text[i]);
  }
  return out;
}

std::string Token::describe() const {
  switch (kind) {
    case TokenKind::Word: return fmt::format("\"{}\"", excerpt(text));
    case TokenKind::String: return fmt::format("string \"{}\"", excerpt(text));
    case TokenKind::OpenBracket: return "'['";
    case TokenKind::CloseBracket: return "']'";
    case TokenKind::End: break;
  }
  return "end of file";
}

// One file's text and the reading position in it.
struct Tokenizer::Source {
  std::string text;
  TokenFile file;
  size_t pos = 0;
  size_t line_start = 0;
  int line = 1;
  int column_of(size_t p) const { return int(p - line_start) + 1; }
};

Tokenizer::Tokenizer(std::string text, std::string filename)
    : Tokenizer(std::move(text), TokenFile{std::move(filename), "", ""}) {}

Tokenizer::Tokenizer(std::string text, TokenFile file) { include(std::move(text), std::move(file)); }

Tokenizer::~Tokenizer() = default;

void Tokenizer::include(std::string text, TokenFile file) {
  if (peeked_) throw std::logic_error("Tokenizer::include with a token peeked");
  auto s = std::make_unique<Source>(Source{std::move(text), std::move(file)});
  auto byte = [&](size_t i) { return i < s->text.size() ? (unsigned char)s->text[i] : 0u; };
  if ((byte(0) == 0xfe && byte(1) == 0xff) || (byte(0) == 0xff && byte(1) == 0xfe))
    throw_error(SourceLoc{s->file.name, 1, 1}, "file is UTF-16 encoded; save it as UTF-8 or ASCII");
  if (byte(0) == 0xef && byte(1) == 0xbb && byte(2) == 0xbf) s->pos = s->line_start = 3;  // UTF-8 BOM
  open_.push_back(std::move(s));
}

void Tokenizer::release_finished() { finished_.clear(); }

const TokenFile& Tokenizer::current_file() const { return open_.back()->file; }

std::vector<const TokenFile*> Tokenizer::open_files() const {
  std::vector<const TokenFile*> files;
  for (const auto& s : open_) files.push_back(&s->file);
  return files;
}

void Tokenizer::fail_at(const Source& s, size_t pos, const std::string& message) const {
  throw_error(SourceLoc{s.file.name, s.line, s.column_of(pos)}, message);
}

const Token& Tokenizer::peek() {
  if (!peeked_) peeked_ = scan();
  return *peeked_;
}

Token Tokenizer::next() {
  Token t = peeked_ ? *peeked_ : scan();
  peeked_.reset();
  if (t.kind == TokenKind::End) took_end_ = true;
  return t;
}

// An included file that has ended gives way to the file that included it; only the end of the
// outermost text is the end.
Token Tokenizer::scan() {
  for (;;) {
    Token t = scan_in(*open_.back());
    if (t.kind != TokenKind::End || open_.size() == 1) return t;
    finished_.push_back(std::move(open_.back()));
    open_.pop_back();
  }
}

Token Tokenizer::scan_in(Source& s) {
  const std::string& text = s.text;
  const size_t n = text.size();
  size_t& pos = s.pos;
  while (pos < n) {
    char c = text[pos];
    if (c == '\n') {
      ++pos;
      ++s.line;
      s.line_start = pos;
      continue;
    }
    if (is_space(c)) {
      ++pos;
      continue;
    }
    if (c == '#') {
      while (pos < n && text[pos] != '\n') ++pos;
      continue;
    }
    int column = s.column_of(pos);
    if (c == '"') return scan_string(s, s.line, column);
    if (c == '[' || c == ']') {
      ++pos;
      TokenKind kind = c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket;
      return Token{kind, std::string_view(text).substr(pos - 1, 1), s.line, column, false, &s.file};
    }
    size_t start = pos;
    while (pos < n && !ends_word(text[pos])) ++pos;
    return Token{TokenKind::Word, std::string_view(text).substr(start, pos - start), s.line, column, false, &s.file};
  }
  return Token{TokenKind::End, {}, s.line, s.column_of(n), false, &s.file};
}

Token Tokenizer::scan_string(Source& s, int line, int column) {
  const std::string& text = s.text;
  const size_t n = text.size();
  size_t& pos = s.pos;
  const size_t start = ++pos;
  auto unterminated = [&](const char* why) {
    std::string_view so_far = std::string_view(text).substr(start, pos - start);
    throw_error(SourceLoc{s.file.name, line, column},
                fmt::format("unterminated string \"{}\": {}", excerpt(so_far), why));
  };
  bool escapes = false;
  while (true) {
    if (pos >= n) unterminated("end of file before the closing quote");
    char c = text[pos];
    if (c == '"') break;
    if (c == '\n') unterminated("end of line before the closing quote");
    if (c == '\\') {
      if (pos + 1 >= n) unterminated("end of file before the closing quote");
      char e = text[pos + 1];
      if (!is_known_escape(e))
        fail_at(s, pos,
                e == '\n' ? std::string("unterminated string: backslash at the end of a line")
                          : fmt::format("unknown escape sequence \"\\{}\" in string", e));
      escapes = true;
      pos += 2;
      continue;
    }
    ++pos;
  }
  Token t{TokenKind::String, std::string_view(text).substr(start, pos - start), line, column, escapes, &s.file};
  ++pos;  // closing quote
  return t;
}

NumberStatus parse_number(std::string_view text, double* value) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  // std::from_chars rejects a leading '+', which pbrt files do use.
  if (begin != end && *begin == '+') {
    ++begin;
    if (begin != end && (*begin == '+' || *begin == '-')) return NumberStatus::NotANumber;
  }
  if (begin == end) return NumberStatus::NotANumber;
  double v = 0;
  auto [ptr, ec] = std::from_chars(begin, end, v, std::chars_format::general);
  if (ec == std::errc::invalid_argument || ptr != end) return NumberStatus::NotANumber;
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports underflow and overflow alike; strtod tells them apart.
    std::string copy(begin, end);
    double d = std::strtod(copy.c_str(), nullptr);
    if (std::isinf(d)) return NumberStatus::OutOfRange;
    *value = d;
    return NumberStatus::Ok;
  }
  if (!std::isfinite(v)) return NumberStatus::NotFinite;
  *value = v;
  return NumberStatus::Ok;
}

}  // namespace eyetrace
