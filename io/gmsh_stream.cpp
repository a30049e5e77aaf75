#include "io/gmsh_stream.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "framework/core/error.h"

namespace voroseal {

namespace {

// Little-endian bytes to an unsigned integer, whatever the host's byte order.
uint64_t little_endian(const unsigned char* b, size_t bytes) {
  uint64_t v = 0;
  for (size_t k = bytes; k-- > 0;) v = (v << 8) | b[k];
  return v;
}

}  // namespace

MshStream::MshStream(const TextSource& source) : source_(source), text_all_(source.text()) {}

bool MshStream::next() {
  if (pos_ >= text_all_.size()) {
    text_ = {};
    tokens_.clear();
    return false;
  }
  const std::string_view window = text_all_.substr(pos_, kMaxLineBytes + 1);
  const size_t found = window.find('\n');
  line_start_ = pos_;
  started_ = true;
  if (found == std::string_view::npos && window.size() > kMaxLineBytes)
    fail("line longer than " + std::to_string(kMaxLineBytes >> 20) + " MiB: not a text line");
  const size_t end = found == std::string_view::npos ? text_all_.size() : pos_ + found;
  text_ = text_all_.substr(pos_, end - pos_);
  while (!text_.empty() && text_.back() == '\r') text_.remove_suffix(1);
  pos_ = end < text_all_.size() ? end + 1 : end;
  tokenize();
  return true;
}

bool MshStream::next_nonblank() {
  while (next())
    if (!tokens_.empty()) return true;
  return false;
}

bool MshStream::skip_to_line(std::string_view token) {
  for (size_t at = text_all_.find(token, pos_); at != std::string_view::npos;
       at = text_all_.find(token, at + 1)) {
    // A match counts when only blanks precede it on its line and a blank or the end follows.
    size_t start = at;
    while (start > pos_ && is_blank(text_all_[start - 1])) --start;
    const bool line_begins = start == pos_ || text_all_[start - 1] == '\n';
    const size_t after = at + token.size();
    const bool token_ends =
        after == text_all_.size() || is_blank(text_all_[after]) || text_all_[after] == '\n';
    if (line_begins && token_ends) {
      pos_ = start;
      return next();
    }
  }
  return false;
}

void MshStream::tokenize() { split_tokens(text_, tokens_); }

long long MshStream::integer(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  long long v = 0;
  if (!parse_integer(tokens_[i], v))
    fail(std::string("expected an integer ") + what + ", found " + quoted_token(tokens_[i]));
  return v;
}

double MshStream::real(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  double v = 0;
  if (!parse_finite_real(tokens_[i], v))
    fail(std::string("expected a finite number ") + what + ", found " + quoted_token(tokens_[i]));
  return v;
}

void MshStream::require(size_t n, const char* what) const {
  if (tokens_.size() < n)
    fail("expected " + std::to_string(n) + " values on the line for " + what + ", found " +
         std::to_string(tokens_.size()));
}

long MshStream::line() const {
  if (!started_) return 0;
  const auto head = text_all_.substr(0, line_start_);
  return 1 + static_cast<long>(std::count(head.begin(), head.end(), '\n'));
}

void MshStream::fail(const std::string& message) const {
  throw InputError(source_.name(), line(), message);
}

void MshStream::fail_at_byte(size_t offset, const std::string& message) const {
  throw InputError(source_.name(), line(), "byte " + std::to_string(offset) + ": " + message);
}

void MshStream::require_items(size_t at, uint64_t count, uint64_t item_bytes,
                              const std::string& what) const {
  if (count > remaining_bytes() / item_bytes)
    fail_at_byte(
        at, what + " = " + std::to_string(count) + " is more than the rest of the file can hold");
}

const unsigned char* MshStream::take(size_t bytes, const char* what) {
  if (bytes > remaining_bytes())
    fail_at_byte(pos_, std::string("file ends where ") + what + " was expected");
  const auto* b = reinterpret_cast<const unsigned char*>(text_all_.data() + pos_);
  pos_ += bytes;
  return b;
}

int32_t MshStream::int32(const char* what) {
  const uint32_t u = static_cast<uint32_t>(little_endian(take(4, what), 4));
  int32_t v = 0;
  std::memcpy(&v, &u, 4);  // two's complement, without implementation-defined conversion
  return v;
}

uint64_t MshStream::unsigned_integer(size_t bytes, const char* what) {
  return little_endian(take(bytes, what), bytes);
}

double MshStream::real64(const char* what) {
  const size_t at = pos_;
  const uint64_t u = little_endian(take(8, what), 8);
  double v = 0;
  std::memcpy(&v, &u, 8);
  if (!std::isfinite(v)) fail_at_byte(at, std::string(what) + " is not a finite number");
  return v;
}

void MshStream::skip(uint64_t bytes, const char* what) {
  if (bytes > remaining_bytes()) fail_at_byte(pos_, std::string("file ends inside ") + what);
  pos_ += bytes;
}

}  // namespace voroseal
