// A cursor over the raw bytes of a Gmsh .msh input (internal to voroseal_io).
//
// A binary .msh file interleaves text lines ("$Nodes", the $PhysicalNames entries) and binary
// blocks, so one position serves both: the line scanner reads a text line at it and the binary
// reads take their bytes from it, and the next line is scanned where a binary block ends.
// Text lines are read as LineReader reads them (tokens, strict numbers, the same messages);
// binary values are little-endian. Errors name "file:line" with the line of the last text line
// read, counted from the bytes, and "byte N" for a binary value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/line_reader.h"

namespace voroseal {

class MshStream {
 public:
  explicit MshStream(const TextSource& source);

  // ---- text lines ----

  /// Moves to the next line that has a token; false at the end (the line stays the last one).
  bool next_nonblank();
  /// Moves to the next line whose first token is `token` and makes it the current line; false
  /// (nothing moved) when there is none. Scans the bytes, so that binary data in between is
  /// skipped whatever it holds.
  bool skip_to_line(std::string_view token);

  size_t size() const { return tokens_.size(); }
  std::string_view operator[](size_t i) const { return tokens_[i]; }
  /// The current line, '\r' stripped.
  std::string_view text() const { return text_; }
  long long integer(size_t i, const char* what) const;
  double real(size_t i, const char* what) const;
  /// Fails unless the line has at least n tokens.
  void require(size_t n, const char* what) const;
  /// 1-based number of the current line; 0 before the first.
  long line() const;
  [[noreturn]] void fail(const std::string& message) const;

  // ---- binary values, read at the position (just after the current line or a binary block) ----

  size_t offset() const { return pos_; }
  /// Bytes from the position to the end of the input.
  size_t remaining_bytes() const { return text_all_.size() - pos_; }
  /// Fails, naming the count read at byte `at`, unless `count` items of `item_bytes` bytes each
  /// fit in the rest of the input: a declared count is checked before anything is allocated.
  void require_items(size_t at, uint64_t count, uint64_t item_bytes, const std::string& what) const;
  int32_t int32(const char* what);
  /// An unsigned integer of `bytes` bytes (4 or 8: the size_t of MSH 4.1 files).
  uint64_t unsigned_integer(size_t bytes, const char* what);
  /// A double that must be finite.
  double real64(const char* what);
  void skip(uint64_t bytes, const char* what);
  [[noreturn]] void fail_at_byte(size_t offset, const std::string& message) const;

 private:
  bool next();
  void tokenize();
  // The bytes of a binary value of `bytes` bytes at the position, which then moves past it.
  const unsigned char* take(size_t bytes, const char* what);

  const TextSource& source_;
  std::string_view text_all_;
  size_t pos_ = 0;         // start of the next line or binary value
  size_t line_start_ = 0;  // offset of the current line
  bool started_ = false;   // a line has been read
  std::string_view text_;
  std::vector<std::string_view> tokens_;
};

}  // namespace voroseal
