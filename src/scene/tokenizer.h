// Splits pbrt-v4 scene text into tokens (bare words, quoted strings, brackets), each with
// its file, line and column, so every later error can point at file:line:col. Comments (# to
// end of line) are skipped here. Tokens are views into the tokenizer's buffers: no allocation
// per token, which keeps multi-million-number meshes fast. Included files are spliced in at
// the token level, as pbrt-v4 does: a directive or a parameter list may go on across the end
// of an included file.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace eyetrace {

enum class TokenKind { Word, String, OpenBracket, CloseBracket, End };

// A file (or text) tokens come from, as the parser describes it.
struct TokenFile {
  std::string name;       // as written in messages
  std::string canonical;  // for recursion checks ("" for text given on the command line)
  std::string dir;        // where an Include in it looks first
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // a word as written; a string's contents between the quotes, raw
  int line = 0;
  int column = 0;
  bool has_escapes = false;         // a string containing backslash escapes (already validated)
  const TokenFile* file = nullptr;  // owned by the tokenizer

  // A quoted string's contents with escapes decoded.
  std::string string_value() const;
  // How the token reads in a message: "Shape", string "abc", '[', end of file.
  std::string describe() const;
};

class Tokenizer {
 public:
  Tokenizer(std::string text, std::string filename);
  Tokenizer(std::string text, TokenFile file);
  Tokenizer(const Tokenizer&) = delete;  // tokens point into the texts
  Tokenizer& operator=(const Tokenizer&) = delete;
  ~Tokenizer();

  Token next();
  const Token& peek();
  // True once next() has handed out the end of the text: a reader that asked for more than
  // the text holds (an unclosed '[' or a value missing at the end) has run into it.
  bool took_end() const { return took_end_; }
  // Splices `text` in at the current point (pbrt-v4's Include and Import): the next tokens
  // are its own, then those after the current point. Nothing may be peeked.
  void include(std::string text, TokenFile file);
  // The innermost file still being read, and every open file, outermost first.
  const TokenFile& current_file() const;
  std::vector<const TokenFile*> open_files() const;
  // Frees the text of included files that have ended: call it only when no token is held.
  void release_finished();
  const std::string& filename() const { return current_file().name; }
  SourceLoc loc(const Token& t) const { return SourceLoc{t.file ? t.file->name : filename(), t.line, t.column}; }

 private:
  struct Source;
  Token scan();
  Token scan_in(Source& s);
  Token scan_string(Source& s, int line, int column);
  [[noreturn]] void fail_at(const Source& s, size_t pos, const std::string& message) const;

  std::vector<std::unique_ptr<Source>> open_;      // innermost last
  std::vector<std::unique_ptr<Source>> finished_;  // ended includes, kept while tokens may point in
  std::optional<Token> peeked_;
  bool took_end_ = false;
};

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

// Parses a whole token as a decimal floating-point number ("1", "-.5", "+2e3"). "nan" and
// "inf" are kNotFinite; magnitudes beyond double range are kOutOfRange; underflow gives 0.
NumberStatus parse_number(std::string_view text, double* value);

}  // namespace eyetrace
