#include "scene/tokenizer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

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

Tokenizer::Tokenizer(std::string text, std::string filename) : text_(std::move(text)), filename_(std::move(filename)) {
  auto byte = [&](size_t i) { return i < text_.size() ? (unsigned char)text_[i] : 0u; };
  if ((byte(0) == 0xfe && byte(1) == 0xff) || (byte(0) == 0xff && byte(1) == 0xfe))
    throw_error(SourceLoc{filename_, 1, 1}, "file is UTF-16 encoded; save it as UTF-8 or ASCII");
  if (byte(0) == 0xef && byte(1) == 0xbb && byte(2) == 0xbf) pos_ = line_start_ = 3;  // UTF-8 BOM
}

void Tokenizer::fail_at(size_t pos, const std::string& message) const {
  throw_error(SourceLoc{filename_, line_, column_of(pos)}, message);
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

Token Tokenizer::scan() {
  const size_t n = text_.size();
  while (pos_ < n) {
    char c = text_[pos_];
    if (c == '\n') {
      ++pos_;
      ++line_;
      line_start_ = pos_;
      continue;
    }
    if (is_space(c)) {
      ++pos_;
      continue;
    }
    if (c == '#') {
      while (pos_ < n && text_[pos_] != '\n') ++pos_;
      continue;
    }
    int column = column_of(pos_);
    if (c == '"') return scan_string(line_, column);
    if (c == '[' || c == ']') {
      ++pos_;
      TokenKind kind = c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket;
      return Token{kind, std::string_view(text_).substr(pos_ - 1, 1), line_, column};
    }
    size_t start = pos_;
    while (pos_ < n && !ends_word(text_[pos_])) ++pos_;
    return Token{TokenKind::Word, std::string_view(text_).substr(start, pos_ - start), line_, column};
  }
  return Token{TokenKind::End, {}, line_, column_of(n)};
}

Token Tokenizer::scan_string(int line, int column) {
  const size_t n = text_.size();
  const size_t start = ++pos_;
  auto unterminated = [&](const char* why) {
    std::string_view so_far = std::string_view(text_).substr(start, pos_ - start);
    throw_error(SourceLoc{filename_, line, column},
                fmt::format("unterminated string \"{}\": {}", excerpt(so_far), why));
  };
  bool escapes = false;
  while (true) {
    if (pos_ >= n) unterminated("end of file before the closing quote");
    char c = text_[pos_];
    if (c == '"') break;
    if (c == '\n') unterminated("end of line before the closing quote");
    if (c == '\\') {
      if (pos_ + 1 >= n) unterminated("end of file before the closing quote");
      char e = text_[pos_ + 1];
      if (!is_known_escape(e))
        fail_at(pos_, e == '\n' ? std::string("unterminated string: backslash at the end of a line")
                                : fmt::format("unknown escape sequence \"\\{}\" in string", e));
      escapes = true;
      pos_ += 2;
      continue;
    }
    ++pos_;
  }
  Token t{TokenKind::String, std::string_view(text_).substr(start, pos_ - start), line, column, escapes};
  ++pos_;  // closing quote
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
