#include "io/line_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "framework/core/error.h"

namespace voroseal {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    while (i < n && is_blank(line[i])) ++i;
    if (i >= n) break;
    const size_t start = i;
    while (i < n && !is_blank(line[i])) ++i;
    tokens.push_back(line.substr(start, i - start));
  }
}

std::string quoted_token(std::string_view token) {
  std::string out;
  for (char c : token.substr(0, 40))
    out += (static_cast<unsigned char>(c) < 32 || c == 127) ? '?' : c;
  if (token.size() > 40) out += "...";
  return "'" + out + "'";
}

TextSource::TextSource(std::string name, std::string text) : name_(std::move(name)) {
  auto owned = std::make_shared<const std::string>(std::move(text));
  text_ = *owned;
  storage_ = std::move(owned);
}

TextSource::TextSource(std::string name, std::shared_ptr<const void> storage, std::string_view text)
    : name_(std::move(name)), storage_(std::move(storage)), text_(text) {}

TextSource load_text(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, not a model file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path, 0, "cannot open file");
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    // A mapping costs no reading until a page is touched: a 2 GB file whose header claims more
    // than it holds is refused at once. The mapping outlives the descriptor.
    const auto size = static_cast<size_t>(st.st_size);
    void* data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (data == MAP_FAILED) throw InputError(path, 0, "cannot read file");
    ::madvise(data, size, MADV_SEQUENTIAL);
    std::shared_ptr<const void> mapping(
        data, [size](const void* p) { ::munmap(const_cast<void*>(p), size); });
    return TextSource(path, std::move(mapping),
                      std::string_view(static_cast<const char*>(data), size));
  }
  ::close(fd);
  std::ifstream in(path, std::ios::binary);  // a pipe, a special file or an empty file
  if (!in) throw InputError(path, 0, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "cannot read file");
  return TextSource(path, text.str());
}

bool parse_integer(std::string_view token, long long& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || token[0] == '+') return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool parse_finite_real(std::string_view token, double& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || token[0] == '+') return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

LineReader::LineReader(const TextSource& source) : source_(source) {}

bool LineReader::next() {
  if (replay_) {
    replay_ = false;
    return true;
  }
  const std::string_view s = source_.text();
  if (pos_ >= s.size()) {
    text_ = {};
    tokens_.clear();
    return false;
  }
  // The newline is looked for within kMaxLineBytes only: a binary or corrupt file is refused
  // after reading that much, not after reading all of it.
  const std::string_view window = s.substr(pos_, kMaxLineBytes + 1);
  const size_t found = window.find('\n');
  if (found == std::string_view::npos && window.size() > kMaxLineBytes)
    fail_at(line_ + 1, "line longer than " + std::to_string(kMaxLineBytes >> 20) +
                           " MiB: not a text model file");
  const size_t end = found == std::string_view::npos ? s.size() : pos_ + found;
  text_ = s.substr(pos_, end - pos_);
  while (!text_.empty() && text_.back() == '\r') text_.remove_suffix(1);
  pos_ = end < s.size() ? end + 1 : end;
  ++line_;
  tokenize();
  return true;
}

bool LineReader::next_nonblank() {
  while (next())
    if (!tokens_.empty()) return true;
  return false;
}

void LineReader::tokenize() {
  split_tokens(text_, tokens_);
}

std::string LineReader::rest(size_t i) const {
  std::string out;
  for (size_t k = i; k < tokens_.size(); ++k) {
    if (!out.empty()) out += ' ';
    out.append(tokens_[k]);
  }
  return out;
}

std::string LineReader::rest_text(size_t i) const {
  if (i >= tokens_.size()) return "";
  std::string_view r = text_.substr(static_cast<size_t>(tokens_[i].data() - text_.data()));
  while (!r.empty() && is_blank(r.back())) r.remove_suffix(1);
  return std::string(r);
}

long long LineReader::integer(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  long long v = 0;
  if (!parse_integer(tokens_[i], v))
    fail(std::string("expected an integer ") + what + ", found " + quoted_token(tokens_[i]));
  return v;
}

double LineReader::real(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  double v = 0;
  if (!parse_finite_real(tokens_[i], v))
    fail(std::string("expected a finite number ") + what + ", found " + quoted_token(tokens_[i]));
  return v;
}

void LineReader::require(size_t n, const char* what) const {
  if (tokens_.size() < n)
    fail(std::string("expected ") + std::to_string(n) + " values on the line for " + what +
         ", found " + std::to_string(tokens_.size()));
}

void LineReader::fail(const std::string& message) const {
  throw InputError(source_.name(), line_, message);
}

void LineReader::fail_at(long line, const std::string& message) const {
  throw InputError(source_.name(), line, message);
}

std::string_view TokenReader::peek() {
  if (!peeked_) {
    while (index_ >= lines_.size() || lines_[index_][0] == '#') {
      if (!lines_.next()) return {};
      index_ = 0;
    }
    peeked_ = true;
  }
  return lines_[index_];
}

std::string_view TokenReader::next() {
  const std::string_view t = peek();
  if (!t.empty()) {
    ++index_;
    peeked_ = false;
  }
  return t;
}

long long TokenReader::integer(const char* what) {
  const std::string_view t = next();
  if (t.empty()) fail(std::string("file ends where ") + what + " was expected");
  long long v = 0;
  if (!parse_integer(t, v))
    fail(std::string("expected an integer ") + what + ", found " + quoted_token(t));
  return v;
}

double TokenReader::real(const char* what) {
  const std::string_view t = next();
  if (t.empty()) fail(std::string("file ends where ") + what + " was expected");
  double v = 0;
  if (!parse_finite_real(t, v))
    fail(std::string("expected a finite number ") + what + ", found " + quoted_token(t));
  return v;
}

}  // namespace voroseal
