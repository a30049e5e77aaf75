// The bytes of binary VTK XML DataArrays (internal to voroseal_io): base64 or raw data, a
// header giving the byte count (UInt32 or UInt64), or VTK's zlib block table (block count,
// block size, last block size, compressed sizes) followed by zlib blocks.
//
// Reading checks every size in a header against the bytes that follow before it allocates,
// and inflates each block into exactly its declared size, so a hostile file fails with an
// InputError naming the file and the line of its DataArray.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace voroseal {

/// The file and line an array's errors are reported at (its DataArray tag).
struct DataPlace {
  const std::string& file;
  long line;
  [[noreturn]] void fail(const std::string& message) const;
};

/// Bytes read from raw data or from base64 text. Base64 text may hold whitespace and several
/// padded parts one after the other (VTK encodes a compressed array's header apart from its
/// data), read as one byte stream.
class VtkBytes {
 public:
  VtkBytes(std::string_view data, bool base64, const DataPlace& place)
      : data_(data), base64_(base64), place_(place) {}

  /// The bytes left: exact for raw data, an upper bound for base64 text.
  uint64_t max_bytes() const;
  /// Reads n bytes. \throws InputError when the data ends first or is not base64.
  void read(unsigned char* out, size_t n);
  /// A little-endian unsigned integer of `size` bytes (4 or 8).
  uint64_t read_uint(int size);

 private:
  void next_quantum();

  std::string_view data_;
  bool base64_;
  const DataPlace& place_;
  size_t pos_ = 0;
  unsigned char quantum_[3] = {0, 0, 0};  // the last decoded base64 group
  int have_ = 0, used_ = 0;               // bytes in quantum_, bytes of it already read
};

/// One binary DataArray: its header, then its bytes.
class VtkArrayReader {
 public:
  /// `header_size`: 4 (header_type UInt32) or 8 (UInt64); `zlib`: compressed blocks.
  VtkArrayReader(VtkBytes& in, int header_size, bool zlib, const DataPlace& place)
      : in_(in), header_size_(header_size), zlib_(zlib), place_(place) {}

  /// Reads the header and returns the array's size in bytes once inflated; the sizes it
  /// declares fit in the data that follows. Call before read_data().
  uint64_t read_header();
  /// The array's bytes, read_header() of them. \throws InputError
  std::vector<unsigned char> read_data();

 private:
  void read_block_table();
  void inflate_block(size_t k, const std::vector<unsigned char>& in, unsigned char* out,
                     uint64_t size);

  VtkBytes& in_;
  int header_size_;
  bool zlib_;
  const DataPlace& place_;
  uint64_t size_ = 0;                 // inflated bytes of the array
  uint64_t block_ = 0, last_ = 0;     // inflated block size; last block's (0: a full block)
  std::vector<uint64_t> compressed_;  // compressed size of each block
};

/// A DataArray type: Int8 ... UInt64, Float32, Float64.
struct VtkType {
  const char* name;
  int size;  // bytes
  bool real;
  bool is_signed;
};
/// The type named `name`; nullptr when unknown.
const VtkType* vtk_type(const std::string& name);
/// The little-endian value at `p` as a double.
double vtk_real(const unsigned char* p, const VtkType& type);
/// The little-endian integer at `p`; false when it does not fit a long long (a large UInt64).
bool vtk_integer(const unsigned char* p, const VtkType& type, long long& value);

/// `size` bytes as VTK writes an inline DataArray with format="binary", header_type="UInt64"
/// and compressor="vtkZLibDataCompressor": base64(block table) then base64(zlib blocks).
std::string vtk_zlib_base64(const unsigned char* data, size_t size);

/// The values' little-endian bytes (integers or IEEE floats), as VTK binary data holds them.
template <class T>
std::vector<unsigned char> little_endian_bytes(const std::vector<T>& values) {
  static_assert(sizeof(T) == 1 || sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8);
  std::vector<unsigned char> out;
  out.reserve(values.size() * sizeof(T));
  for (const T& v : values) {
    uint64_t bits = 0;
    if constexpr (sizeof(T) == 1) bits = static_cast<uint8_t>(v);
    if constexpr (sizeof(T) == 2) bits = static_cast<uint16_t>(v);
    if constexpr (sizeof(T) == 4) {
      uint32_t b;
      std::memcpy(&b, &v, 4);
      bits = b;
    }
    if constexpr (sizeof(T) == 8) std::memcpy(&bits, &v, 8);
    for (size_t i = 0; i < sizeof(T); ++i)
      out.push_back(static_cast<unsigned char>(bits >> (8 * i)));
  }
  return out;
}

}  // namespace voroseal
