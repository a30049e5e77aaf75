#include "io/line_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/core/error.h"

namespace voroseal {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string quoted(std::string_view token) {
  // Keep messages short and printable even for binary garbage.
  std::string out;
  for (char c : token.substr(0, 40)) out += (static_cast<unsigned char>(c) < 32 || c == 127) ? '?' : c;
  if (token.size() > 40) out += "...";
  return "'" + out + "'";
}

}  // namespace

TextSource load_text(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, not a model file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open file");
  // One allocation of the file's size where it has one (not a pipe), not a growing buffer.
  TextSource source{path, {}};
  const std::uintmax_t size =
      std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  if (!ec && size > 0) {
    source.text.resize(static_cast<size_t>(size));
    in.read(source.text.data(), static_cast<std::streamsize>(size));
    source.text.resize(static_cast<size_t>(in.gcount()));
    if (in.bad()) throw InputError(path, 0, "cannot read file");
    in.clear();
  }
  std::ostringstream rest;  // what a growing file or a pipe holds beyond its size
  rest << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "cannot read file");
  source.text += rest.str();
  return source;
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
  const std::string& s = source_.text;
  if (pos_ >= s.size()) {
    text_ = {};
    tokens_.clear();
    return false;
  }
  size_t end = s.find('\n', pos_);
  if (end == std::string::npos) end = s.size();
  text_ = std::string_view(s).substr(pos_, end - pos_);
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
  tokens_.clear();
  size_t i = 0;
  const size_t n = text_.size();
  while (i < n) {
    while (i < n && is_space(text_[i])) ++i;
    if (i >= n) break;
    const size_t start = i;
    while (i < n && !is_space(text_[i])) ++i;
    tokens_.push_back(text_.substr(start, i - start));
  }
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
  while (!r.empty() && is_space(r.back())) r.remove_suffix(1);
  return std::string(r);
}

long long LineReader::integer(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  long long v = 0;
  if (!parse_integer(tokens_[i], v)) fail(std::string("expected an integer ") + what + ", found " + quoted(tokens_[i]));
  return v;
}

double LineReader::real(size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  double v = 0;
  if (!parse_finite_real(tokens_[i], v))
    fail(std::string("expected a finite number ") + what + ", found " + quoted(tokens_[i]));
  return v;
}

void LineReader::require(size_t n, const char* what) const {
  if (tokens_.size() < n)
    fail(std::string("expected ") + std::to_string(n) + " values on the line for " + what + ", found " +
         std::to_string(tokens_.size()));
}

void LineReader::fail(const std::string& message) const { throw InputError(source_.name, line_, message); }

void LineReader::fail_at(long line, const std::string& message) const {
  throw InputError(source_.name, line, message);
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
  if (!parse_integer(t, v)) fail(std::string("expected an integer ") + what + ", found " + quoted(t));
  return v;
}

double TokenReader::real(const char* what) {
  const std::string_view t = next();
  if (t.empty()) fail(std::string("file ends where ") + what + " was expected");
  double v = 0;
  if (!parse_finite_real(t, v)) fail(std::string("expected a finite number ") + what + ", found " + quoted(t));
  return v;
}

}  // namespace voroseal
