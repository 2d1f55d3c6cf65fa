// Splits pbrt-v4 scene text into tokens (bare words, quoted strings, brackets), each with
// its line and column, so every later error can point at file:line:col. Comments (# to end
// of line) are skipped here. Tokens are views into the tokenizer's buffer: no allocation per
// token, which keeps multi-million-number meshes fast.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace eyetrace {

enum class TokenKind { Word, String, OpenBracket, CloseBracket, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // a word as written; a string's contents between the quotes, raw
  int line = 0;
  int column = 0;
  bool has_escapes = false;  // a string containing backslash escapes (already validated)

  // A quoted string's contents with escapes decoded.
  std::string string_value() const;
  // How the token reads in a message: "Shape", string "abc", '[', end of file.
  std::string describe() const;
};

class Tokenizer {
 public:
  Tokenizer(std::string text, std::string filename);
  Tokenizer(const Tokenizer&) = delete;  // tokens point into text_
  Tokenizer& operator=(const Tokenizer&) = delete;

  Token next();
  const Token& peek();
  // True once next() has handed out the end of the text: a reader that asked for more than
  // the text holds (an unclosed '[' or a value missing at the end) has run into it.
  bool took_end() const { return took_end_; }
  const std::string& filename() const { return filename_; }
  SourceLoc loc(const Token& t) const { return SourceLoc{filename_, t.line, t.column}; }

 private:
  Token scan();
  Token scan_string(int line, int column);
  [[noreturn]] void fail_at(size_t pos, const std::string& message) const;
  int column_of(size_t pos) const { return int(pos - line_start_) + 1; }

  std::string text_;
  std::string filename_;
  size_t pos_ = 0;
  size_t line_start_ = 0;
  int line_ = 1;
  std::optional<Token> peeked_;
  bool took_end_ = false;
};

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

// Parses a whole token as a decimal floating-point number ("1", "-.5", "+2e3"). "nan" and
// "inf" are kNotFinite; magnitudes beyond double range are kOutOfRange; underflow gives 0.
NumberStatus parse_number(std::string_view text, double* value);

}  // namespace eyetrace
