#include "io/vtk_binary.h"

#include <zlib.h>

#include <algorithm>
#include <climits>

#include "framework/core/error.h"

namespace voroseal {

namespace {

// Deflate's largest ratio: a 258-byte match coded in 2 bits. A header that declares more
// inflated bytes than this allows for its compressed ones is refused before allocating.
constexpr uint64_t kMaxInflateRatio = 1032;
// The block size VTK writes (vtkZLibDataCompressor's default) and the zlib level.
constexpr size_t kWriteBlockBytes = 32768;
constexpr int kWriteLevel = Z_DEFAULT_COMPRESSION;

constexpr char kBase64Digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

std::string printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 32 && u < 127) return std::string("'") + c + "'";
  return "byte " + std::to_string(u);
}

std::string base64(const unsigned char* data, size_t size) {
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const size_t n = std::min<size_t>(3, size - i);
    uint32_t group = uint32_t{data[i]} << 16;
    if (n > 1) group |= uint32_t{data[i + 1]} << 8;
    if (n > 2) group |= data[i + 2];
    for (size_t k = 0; k < 4; ++k)
      out += k <= n ? kBase64Digits[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

uint64_t little_endian(const unsigned char* p, int size) {
  uint64_t v = 0;
  for (int i = size - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

void put_uint64(std::vector<unsigned char>& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

}  // namespace

void DataPlace::fail(const std::string& message) const {
  throw InputError(file, line, message);
}

uint64_t VtkBytes::max_bytes() const {
  const uint64_t rest = data_.size() - pos_;
  return base64_ ? rest / 4 * 3 + static_cast<uint64_t>(have_ - used_) : rest;
}

void VtkBytes::read(unsigned char* out, size_t n) {
  if (n == 0) return;  // `out` may be the null data() of an empty array
  if (!base64_) {
    if (n > data_.size() - pos_) place_.fail("the binary data ends inside the array");
    std::memcpy(out, data_.data() + pos_, n);
    pos_ += n;
    return;
  }
  while (n > 0) {
    if (used_ == have_) next_quantum();
    const size_t k = std::min<size_t>(n, static_cast<size_t>(have_ - used_));
    std::memcpy(out, quantum_ + used_, k);
    out += k;
    n -= k;
    used_ += static_cast<int>(k);
  }
}

uint64_t VtkBytes::read_uint(int size) {
  unsigned char b[8] = {};
  read(b, static_cast<size_t>(size));
  return little_endian(b, size);
}

// Decodes the next group of 4 base64 digits. '=' may only pad the end of a group: then the
// group gives fewer than 3 bytes and the next part of the text starts a new group.
void VtkBytes::next_quantum() {
  int digit[4] = {0, 0, 0, 0};
  int count = 0, pad = 0;
  while (count < 4) {
    if (pos_ == data_.size())
      place_.fail(count == 0 ? "the base64 data ends inside the array"
                             : "truncated base64 data (a group of fewer than 4 digits)");
    const char c = data_[pos_++];
    if (is_space(c)) continue;
    if (c == '=' && count >= 2) {
      ++pad;
      ++count;
      continue;
    }
    const int v = base64_value(c);
    if (v < 0 || pad > 0) place_.fail("invalid " + printable(c) + " in base64 data");
    digit[count++] = v;
  }
  const uint32_t group = (digit[0] << 18) | (digit[1] << 12) | (digit[2] << 6) | digit[3];
  for (int k = 0; k < 3; ++k) quantum_[k] = static_cast<unsigned char>(group >> (16 - 8 * k));
  have_ = 3 - pad;
  used_ = 0;
}

uint64_t VtkArrayReader::read_header() {
  if (zlib_) {
    read_block_table();
    return size_;
  }
  size_ = in_.read_uint(header_size_);
  if (size_ > in_.max_bytes())
    place_.fail("the DataArray header declares " + std::to_string(size_) + " bytes but only " +
                std::to_string(in_.max_bytes()) + " follow");
  return size_;
}

// VTK's zlib header: block count, inflated block size, inflated size of the last block (0 when
// it is full), then the compressed size of each block.
void VtkArrayReader::read_block_table() {
  const uint64_t blocks = in_.read_uint(header_size_);
  if (blocks > in_.max_bytes() / static_cast<uint64_t>(header_size_))
    place_.fail("the zlib header declares " + std::to_string(blocks) +
                " blocks, more than the data can hold");
  block_ = in_.read_uint(header_size_);
  last_ = in_.read_uint(header_size_);
  compressed_.resize(blocks);
  for (uint64_t& c : compressed_) c = in_.read_uint(header_size_);
  const uint64_t available = in_.max_bytes();
  uint64_t total = 0;
  for (uint64_t c : compressed_) {
    if (c > available - total)
      place_.fail("the zlib blocks are declared larger than the " + std::to_string(available) +
                  " bytes that follow");
    total += c;
  }
  if (blocks == 0) return;
  if (block_ == 0 || last_ > block_)
    place_.fail("bad zlib block sizes " + std::to_string(block_) + " and " + std::to_string(last_));
  const uint64_t full = blocks - (last_ > 0 ? 1 : 0);
  // The inflated size may not exceed what the compressed bytes can give (no overflow either).
  const uint64_t limit = kMaxInflateRatio * (total + blocks);
  if (full > 0 && block_ > limit / full)
    place_.fail("the zlib header declares blocks of " + std::to_string(block_) +
                " bytes, more than its " + std::to_string(total) + " compressed bytes can hold");
  size_ = full * block_ + last_;
  if (size_ > limit)
    place_.fail("the zlib header declares " + std::to_string(size_) + " bytes, more than its " +
                std::to_string(total) + " compressed bytes can hold");
}

std::vector<unsigned char> VtkArrayReader::read_data() {
  std::vector<unsigned char> out(size_);
  if (!zlib_) {
    in_.read(out.data(), out.size());
    return out;
  }
  std::vector<unsigned char> block;
  uint64_t at = 0;
  for (size_t k = 0; k < compressed_.size(); ++k) {
    const bool partial = k + 1 == compressed_.size() && last_ > 0;
    const uint64_t size = partial ? last_ : block_;
    block.resize(compressed_[k]);
    in_.read(block.data(), block.size());
    inflate_block(k, block, out.data() + at, size);
    at += size;
  }
  return out;
}

// Inflates the compressed bytes of block k into exactly `size` bytes at `out`: a block that
// ends early, would run past `size` or is not zlib data is an error.
void VtkArrayReader::inflate_block(size_t k, const std::vector<unsigned char>& in,
                                   unsigned char* out, uint64_t size) {
  const std::string which = "zlib block " + std::to_string(k + 1);
  if (in.size() > UINT_MAX || size > UINT_MAX) place_.fail(which + " is larger than 4 GiB");
  z_stream z{};
  if (inflateInit(&z) != Z_OK) place_.fail("zlib cannot start inflating");
  unsigned char spare = 0;  // zlib wants an output pointer even for an empty block
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = size > 0 ? out : &spare;
  z.avail_out = static_cast<uInt>(size);
  int result = inflate(&z, Z_FINISH);
  const uInt left = z.avail_out;
  bool more = false;
  if (result != Z_STREAM_END && left == 0) {
    // The block filled its size: one more byte tells a longer block from a stream end.
    z.next_out = &spare;
    z.avail_out = 1;
    result = inflate(&z, Z_FINISH);
    more = z.avail_out == 0;
  }
  inflateEnd(&z);
  if (more)
    place_.fail(which + " inflates to more than the " + std::to_string(size) + " bytes declared");
  if (result == Z_STREAM_END && left == 0) return;
  if (result == Z_STREAM_END)
    place_.fail(which + " inflates to " + std::to_string(size - left) + " bytes, not the " +
                std::to_string(size) + " declared");
  if (result == Z_DATA_ERROR || result == Z_NEED_DICT)
    place_.fail(which + " is not valid zlib data");
  place_.fail(which + " is truncated");
}

const VtkType* vtk_type(const std::string& name) {
  static constexpr VtkType kTypes[] = {{"Int8", 1, false, true},   {"UInt8", 1, false, false},
                                       {"Int16", 2, false, true},  {"UInt16", 2, false, false},
                                       {"Int32", 4, false, true},  {"UInt32", 4, false, false},
                                       {"Int64", 8, false, true},  {"UInt64", 8, false, false},
                                       {"Float32", 4, true, true}, {"Float64", 8, true, true}};
  for (const VtkType& t : kTypes)
    if (name == t.name) return &t;
  return nullptr;
}

double vtk_real(const unsigned char* p, const VtkType& type) {
  const uint64_t bits = little_endian(p, type.size);
  if (type.real && type.size == 4) {
    float f;
    const auto b = static_cast<uint32_t>(bits);
    std::memcpy(&f, &b, 4);
    return f;
  }
  if (type.real) {
    double d;
    std::memcpy(&d, &bits, 8);
    return d;
  }
  long long v = 0;
  if (!vtk_integer(p, type, v)) return static_cast<double>(bits);
  return static_cast<double>(v);
}

bool vtk_integer(const unsigned char* p, const VtkType& type, long long& value) {
  uint64_t bits = little_endian(p, type.size);
  const int width = 8 * type.size;
  if (type.is_signed && width < 64 && (bits >> (width - 1)) != 0) bits |= ~uint64_t{0} << width;
  if (!type.is_signed && bits > static_cast<uint64_t>(LLONG_MAX)) return false;
  value = static_cast<long long>(bits);
  return true;
}

std::string vtk_zlib_base64(const unsigned char* data, size_t size) {
  const size_t blocks = (size + kWriteBlockBytes - 1) / kWriteBlockBytes;
  std::vector<unsigned char> header, body;
  put_uint64(header, blocks);
  put_uint64(header, kWriteBlockBytes);
  put_uint64(header, size % kWriteBlockBytes);
  std::vector<unsigned char> buffer(compressBound(kWriteBlockBytes));
  for (size_t k = 0; k < blocks; ++k) {
    const size_t n = std::min(kWriteBlockBytes, size - k * kWriteBlockBytes);
    uLongf length = static_cast<uLongf>(buffer.size());
    if (compress2(buffer.data(), &length, data + k * kWriteBlockBytes, static_cast<uLong>(n),
                  kWriteLevel) != Z_OK)
      throw OutputError("zlib cannot compress a VTK data array");
    put_uint64(header, length);
    body.insert(body.end(), buffer.begin(), buffer.begin() + static_cast<long>(length));
  }
  return base64(header.data(), header.size()) + base64(body.data(), body.size());
}

}  // namespace voroseal
