// Line-by-line reading of text model files with whitespace tokens, strict number parsing and
// errors that name "file:line" the same way for every reader.
//
// A file is mapped at once (TextSource) so that readers can also run on a buffer (fuzzing)
// and can cap declared element counts by what the file can possibly hold, before reading it.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace voroseal {

/// The whole text of an input, with the name used in messages. The text is either owned or a
/// read-only mapping of the file, so that a header's counts are checked against the file's size
/// before its pages are read.
class TextSource {
 public:
  /// An input held in memory (a buffer, a fuzzer's data).
  TextSource(std::string name, std::string text);

  const std::string& name() const { return name_; }
  std::string_view text() const { return text_; }

 private:
  friend TextSource load_text(const std::string& path);
  TextSource(std::string name, std::shared_ptr<const void> storage, std::string_view text);

  std::string name_;
  std::shared_ptr<const void> storage_;  // the owned string or the mapping, shared by copies
  std::string_view text_;
};

/// Maps a regular file (reads a pipe or a special file). \throws InputError(path, 0, ...) when
/// it cannot be opened or read.
TextSource load_text(const std::string& path);

/// The longest line a text model file may have (a GOCAD name, a Gmsh entity line are far
/// shorter): a binary or corrupt file read as text is refused after that much.
constexpr size_t kMaxLineBytes = size_t{1} << 20;

/// Blanks between tokens: space, tab, '\r', '\v', '\f'.
bool is_blank(char c);
/// `line` split at blanks into `tokens` (cleared first).
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);
/// A token quoted for a message: short and printable even for binary garbage.
std::string quoted_token(std::string_view token);

/// Strict number parsing: the whole token must be the number ('+' sign allowed).
bool parse_integer(std::string_view token, long long& value);
/// Also rejects "nan", "inf" and values that overflow a double.
bool parse_finite_real(std::string_view token, double& value);

class LineReader {
 public:
  explicit LineReader(const TextSource& source);

  /// Moves to the next line (blank lines included; '\r' stripped); false at the end.
  bool next();
  /// Moves to the next line that has at least one token; false at the end.
  bool next_nonblank();
  /// Makes the next call to next() return the current line again.
  void unread() { replay_ = true; }

  long line() const { return line_; }
  std::string_view text() const { return text_; }
  size_t size() const { return tokens_.size(); }
  bool empty() const { return tokens_.empty(); }
  std::string_view operator[](size_t i) const { return tokens_[i]; }
  /// Tokens from i on, joined by one space ("" when there are none).
  std::string rest(size_t i) const;
  /// The text after token i-1, trimmed (keeps inner spacing; for names and comments).
  std::string rest_text(size_t i) const;

  /// Token i as a number; fails naming `what` when it is missing or not a number.
  long long integer(size_t i, const char* what) const;
  double real(size_t i, const char* what) const;
  /// Fails unless the line has at least n tokens.
  void require(size_t n, const char* what) const;

  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_at(long line, const std::string& message) const;

  const std::string& name() const { return source_.name(); }
  /// Size of the whole input and of what is left after the current line, in bytes: a
  /// declared count larger than what the rest can hold is an error, not an allocation.
  size_t bytes() const { return source_.text().size(); }
  size_t remaining_bytes() const { return source_.text().size() - pos_; }

 private:
  void tokenize();

  const TextSource& source_;
  size_t pos_ = 0;  // start of the next line
  long line_ = 0;
  bool replay_ = false;
  std::string_view text_;
  std::vector<std::string_view> tokens_;
};

/// Whitespace tokens read across lines (Medit): every token knows its line.
class TokenReader {
 public:
  explicit TokenReader(const TextSource& source) : lines_(source) {}

  /// Next token, skipping blank lines and '#' comments; empty at the end of the input.
  std::string_view next();
  /// Next token without consuming it.
  std::string_view peek();
  long long integer(const char* what);
  double real(const char* what);
  /// Line of the last token returned (or of the end of the input).
  long line() const { return lines_.line(); }
  [[noreturn]] void fail(const std::string& message) const { lines_.fail(message); }
  /// Bytes not yet consumed (an upper bound), to cap declared counts.
  size_t remaining_bytes() const { return lines_.remaining_bytes() + lines_.text().size(); }
  const std::string& name() const { return lines_.name(); }

 private:
  LineReader lines_;
  size_t index_ = 0;  // next token of the current line
  bool peeked_ = false;
};

}  // namespace voroseal
