// The .vtu reader in every encoding VTK writes (ascii; inline base64 with a UInt32 or UInt64
// header; appended raw or base64; each uncompressed or zlib-compressed), files broken in their
// binary parts, the compressed writer, and files written by meshio (skipped without it).
// The files are encoded here by the test's own code, not by io/vtk_binary.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <sstream>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "io/vtk_format.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using Bytes = std::string;

// ---- the test's VTK encoder ----

std::string base64(const Bytes& b) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < b.size(); i += 3) {
    const size_t n = std::min<size_t>(3, b.size() - i);
    uint32_t g = 0;
    for (size_t k = 0; k < 3; ++k)
      g = (g << 8) | (k < n ? static_cast<unsigned char>(b[i + k]) : 0);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(g >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

void put(Bytes& out, uint64_t v, int size) {
  for (int i = 0; i < size; ++i) out += static_cast<char>(v >> (8 * i));
}

Bytes u64(uint64_t v) {
  Bytes b;
  put(b, v, 8);
  return b;
}

Bytes compress(const Bytes& data) {
  uLongf n = compressBound(data.size());
  Bytes out(n, '\0');
  compress2(reinterpret_cast<Bytef*>(&out[0]), &n, reinterpret_cast<const Bytef*>(data.data()),
            data.size(), 6);
  out.resize(n);
  return out;
}

int size_of(const std::string& type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  return 8;
}

// Values as the little-endian bytes of a VTK type.
Bytes pack(const std::vector<double>& values, const std::string& type) {
  Bytes out;
  for (double v : values) {
    if (type == "Float32") {
      const float f = static_cast<float>(v);
      uint32_t b;
      std::memcpy(&b, &f, 4);
      put(out, b, 4);
    } else if (type == "Float64") {
      uint64_t b;
      std::memcpy(&b, &v, 8);
      put(out, b, 8);
    } else {
      put(out, static_cast<uint64_t>(static_cast<int64_t>(v)), size_of(type));
    }
  }
  return out;
}

struct Encoding {
  std::string name;
  std::string format;            // ascii, binary, appended
  std::string appended = "raw";  // raw or base64 (appended only)
  int header = 4;                // bytes of header_type: 4 (UInt32) or 8 (UInt64)
  bool zlib = false;
  bool split = false;  // base64 of the header apart from the data's (VTK's compressed layout)
};
constexpr size_t kBlock = 16;  // small zlib blocks: several per array and a partial last one

// One binary array as VTK lays it out: its header (byte count or zlib block table), its data.
struct Encoded {
  Bytes header, data;
};

Encoded encode(const Bytes& bytes, const Encoding& e) {
  Encoded out;
  if (!e.zlib) {
    put(out.header, bytes.size(), e.header);
    out.data = bytes;
    return out;
  }
  const size_t blocks = (bytes.size() + kBlock - 1) / kBlock;
  put(out.header, blocks, e.header);
  put(out.header, kBlock, e.header);
  put(out.header, bytes.size() % kBlock, e.header);
  for (size_t k = 0; k < blocks; ++k) {
    const Bytes c = compress(bytes.substr(k * kBlock, kBlock));
    put(out.header, c.size(), e.header);
    out.data += c;
  }
  return out;
}

struct Array {
  std::string section, name, type;
  int components;
  std::vector<double> values;
};

// How a test breaks one array: its encoded bytes, its text (base64 or raw), its attributes.
struct Tamper {
  std::string array;
  std::function<void(Encoded&)> bytes;
  std::function<void(std::string&)> text;
  std::string attributes;  // replaces the format/offset attributes when not empty
};

std::string ascii_text(const Array& a) {
  std::string s;
  char buffer[32];
  for (double v : a.values) {
    std::snprintf(buffer, sizeof buffer, "%.17g ", v);
    s += buffer;
  }
  return s;
}

std::string encoded_text(const Array& a, const Encoding& e, const Tamper& t) {
  Encoded x = encode(pack(a.values, a.type), e);
  if (t.array == a.name && t.bytes) t.bytes(x);
  std::string s;
  if (e.format == "appended" && e.appended == "raw")
    s = x.header + x.data;
  else
    s = e.split ? base64(x.header) + base64(x.data) : base64(x.header + x.data);
  if (t.array == a.name && t.text) t.text(s);
  return s;
}

std::string vtu_file(const std::vector<Array>& arrays, size_t points, size_t cells,
                     const Encoding& e, const Tamper& t = {}) {
  std::string f =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"" +
      std::string(e.header == 8 ? "UInt64" : "UInt32") + "\"" +
      (e.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<UnstructuredGrid>\n" +
      "<Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\"" +
      std::to_string(cells) + "\">\n";
  std::string section, appended;
  for (const Array& a : arrays) {
    if (a.section != section) {
      if (!section.empty()) f += "</" + section + ">\n";
      section = a.section;
      f += "<" + section + ">\n";
    }
    f += "<DataArray type=\"" + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
         std::to_string(a.components) + "\" ";
    const std::string body = e.format == "ascii" ? ascii_text(a) : encoded_text(a, e, t);
    std::string attributes = "format=\"" + e.format + "\"";
    if (e.format == "appended") attributes += " offset=\"" + std::to_string(appended.size()) + "\"";
    if (t.array == a.name && !t.attributes.empty()) attributes = t.attributes;
    if (e.format == "appended") {
      f += attributes + "/>\n";
      appended += body;
    } else {
      f += attributes + ">\n" + body + "\n</DataArray>\n";
    }
  }
  f += "</" + section + ">\n</Piece>\n</UnstructuredGrid>\n";
  if (e.format == "appended")
    f += "<AppendedData encoding=\"" + e.appended + "\">\n   _" + appended + "\n</AppendedData>\n";
  return f + "</VTKFile>\n";
}

// Types of the arrays of a file: points, connectivity, offsets, types, ids.
struct Types {
  std::string points, connectivity, offsets, types, ids;
};

std::vector<Array> mesh_arrays(const VolumeMesh& m, const Types& t) {
  Array points{"Points", "Points", t.points, 3, {}};
  for (const Vec3& v : m.vertices)
    for (int k = 0; k < 3; ++k) points.values.push_back((v + m.frame.origin)[k]);
  Array connectivity{"Cells", "connectivity", t.connectivity, 1, {}};
  Array offsets{"Cells", "offsets", t.offsets, 1, {}}, types{"Cells", "types", t.types, 1, {}};
  Array surface{"CellData", "surface", t.ids, 1, {}}, region{"CellData", "region", t.ids, 1, {}};
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) connectivity.values.push_back(m.triangles[f][k]);
    offsets.values.push_back(static_cast<double>(connectivity.values.size()));
    types.values.push_back(5);
    surface.values.push_back(m.triangle_surface[f]);
    region.values.push_back(-1);
  }
  for (size_t c = 0; c < m.tets.size(); ++c) {
    for (int k = 0; k < 4; ++k) connectivity.values.push_back(m.tets[c][k]);
    offsets.values.push_back(static_cast<double>(connectivity.values.size()));
    types.values.push_back(10);
    surface.values.push_back(-1);
    region.values.push_back(m.tet_region[c]);
  }
  // A point data array the reader skips, in the same encoding.
  Array skipped{"PointData", "temperature", "Float32", 1,
                std::vector<double>(m.vertices.size(), 20.5)};
  return {skipped, points, connectivity, offsets, types, surface, region};
}

std::string mesh_file(const VolumeMesh& m, const Encoding& e, const Types& t = {}) {
  const Types types = t.points.empty() ? Types{"Float64", "Int64", "Int64", "UInt8", "Int32"} : t;
  return vtu_file(mesh_arrays(m, types), m.vertices.size(), m.triangles.size() + m.tets.size(), e);
}

void expect_same_mesh(const VolumeMesh& read, const VolumeMesh& m, double tolerance = 0) {
  ASSERT_EQ(read.vertices.size(), m.vertices.size());
  for (size_t v = 0; v < m.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((read.vertices[v] + read.frame.origin)[k], (m.vertices[v] + m.frame.origin)[k],
                  tolerance);
  EXPECT_EQ(read.tets, m.tets);
  EXPECT_EQ(read.triangles, m.triangles);
  EXPECT_EQ(read.tet_region, m.tet_region);
  EXPECT_EQ(read.triangle_surface, m.triangle_surface);
}

const std::vector<Encoding> kEncodings = {
    {"ascii", "ascii"},
    {"binary_uint32", "binary", "", 4, false, false},
    {"binary_uint32_split_header", "binary", "", 4, false, true},
    {"binary_uint64", "binary", "", 8, false, false},
    {"binary_zlib_uint32", "binary", "", 4, true, true},
    {"binary_zlib_uint64_joined", "binary", "", 8, true, false},
    {"appended_raw", "appended", "raw", 4, false, false},
    {"appended_raw_zlib_uint64", "appended", "raw", 8, true, false},
    {"appended_base64", "appended", "base64", 4, false, false},
    {"appended_base64_zlib", "appended", "base64", 8, true, true},
};

const std::vector<Types> kTypes = {
    {"Float64", "Int64", "Int64", "UInt8", "Int32"},
    {"Float32", "Int32", "UInt32", "Int8", "Int16"},
    {"Float64", "UInt64", "UInt16", "UInt64", "Int64"},
    {"Float64", "UInt32", "Int16", "Int16", "Int8"},
};

class VtuEncoding : public ::testing::TestWithParam<Encoding> {};

TEST_P(VtuEncoding, ReadsEveryTypeBack) {
  const VolumeMesh m = test::cube_tet_mesh();
  for (const Types& t : kTypes) {
    SCOPED_TRACE(t.points + " " + t.connectivity + " " + t.offsets + " " + t.types + " " + t.ids);
    const std::string text = mesh_file(m, GetParam(), t);
    expect_same_mesh(read_vtu_volume(TextSource("cube.vtu", text)), m);
    const SurfaceSoup soup = read_vtu(TextSource("cube.vtu", text));
    EXPECT_EQ(soup.triangles.size(), 12u);
    EXPECT_EQ(soup.groups.size(), 6u);
  }
}

INSTANTIATE_TEST_SUITE_P(AllEncodings, VtuEncoding, ::testing::ValuesIn(kEncodings),
                         [](const auto& info) { return info.param.name; });

TEST(VtuEncodingFile, RawAppendedBytesThatLookLikeXmlAreData) {
  // Ids 60 ('<'), 47 ('/') and 62 ('>'), and a skipped array whose bytes spell the end of the
  // file: the appended data is not scanned as XML.
  std::vector<double> spelled;
  for (char c : std::string("</AppendedData></VTKFile>")) spelled.push_back(c);
  const std::vector<Array> arrays = {
      {"Points", "Points", "Float64", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}},
      {"Cells", "connectivity", "Int32", 1, {0, 1, 2, 1, 3, 2}},
      {"Cells", "offsets", "Int32", 1, {3, 6}},
      {"Cells", "types", "UInt8", 1, {5, 5}},
      {"CellData", "spelled", "UInt8", 1, spelled},
      {"CellData", "surface", "Int32", 1, {60, 62}}};
  const Encoding raw{"raw", "appended", "raw", 4, false, false};
  const std::string text = vtu_file(arrays, 4, 2, raw);
  ASSERT_LT(text.find("</AppendedData></VTKFile>"), text.rfind("</AppendedData>"));
  const SurfaceSoup soup = read_vtu(TextSource("xmlish.vtu", text));
  EXPECT_EQ(soup.triangles.size(), 2u);
  ASSERT_EQ(soup.groups.size(), 2u);
  EXPECT_EQ(soup.groups[0].name, "surface_60");
  EXPECT_EQ(soup.groups[1].name, "surface_62");
}

// ---- broken binary data ----

// A triangle's file in encoding `e`, with one array broken by `t`.
std::string triangle_file(const Encoding& e, const Tamper& t,
                          const std::string& points_type = "Float64",
                          const std::string& connectivity_type = "Int64") {
  const std::vector<Array> arrays = {
      {"Points", "Points", points_type, 3, {0, 0, 0, 1, 0, 0, 0, 1, 0}},
      {"Cells", "connectivity", connectivity_type, 1, {0, 1, 2}},
      {"Cells", "offsets", "Int64", 1, {3}},
      {"Cells", "types", "UInt8", 1, {5}}};
  return vtu_file(arrays, 3, 1, e, t);
}

long line_of(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  return at == std::string::npos
             ? -1
             : 1 + static_cast<long>(std::count(text.begin(), text.begin() + at, '\n'));
}

struct Broken {
  std::string name;
  std::string text;
  long line;
  std::string message;
};

void expect_rejected(const Broken& b) {
  SCOPED_TRACE(b.name);
  try {
    read_vtu(TextSource("broken.vtu", b.text));
    ADD_FAILURE() << "read without error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "broken.vtu");
    EXPECT_EQ(e.line(), b.line) << e.what();
    EXPECT_NE(e.message().find(b.message), std::string::npos) << e.what();
  }
}

const Encoding kInline{"inline", "binary", "", 4, false, false};
const Encoding kInlineZlib{"inline_zlib", "binary", "", 8, true, true};
const Encoding kRaw{"raw", "appended", "raw", 4, false, false};
const Encoding kRawZlib{"raw_zlib", "appended", "raw", 8, true, false};
const Encoding kBase64Zlib{"base64_zlib", "appended", "base64", 8, true, true};

// Points of 9 Float64 (72 bytes) as one zlib block of `inflated` bytes declared as 72.
void one_block_of(Encoded& x, const Bytes& inflated) {
  const Bytes c = compress(inflated);
  x.header.clear();
  for (uint64_t v : {uint64_t{1}, uint64_t{72}, uint64_t{0}, uint64_t{c.size()}})
    put(x.header, v, 8);
  x.data = c;
}

std::vector<Broken> broken_binary_files() {
  auto file = [](const Encoding& e, Tamper t) { return triangle_file(e, t); };
  auto points_line = [](const std::string& text) { return line_of(text, "Name=\"Points\""); };
  std::vector<Broken> cases;
  auto add = [&](const std::string& name, const std::string& text, const std::string& message) {
    cases.push_back({name, text, points_line(text), message});
  };
  add("truncated base64", file(kInlineZlib, {"Points", {}, [](std::string& s) { s.pop_back(); }}),
      "truncated base64 data");
  add("base64 cut at a group",
      file(kInline, {"Points", {}, [](std::string& s) { s.resize(s.size() - 8); }}),
      "declares 72 bytes but only 68 follow");
  add("invalid base64 digit", file(kInline, {"Points", {}, [](std::string& s) { s[5] = '*'; }}),
      "invalid '*' in base64 data");
  add("misplaced padding", file(kInline, {"Points", {}, [](std::string& s) { s[1] = '='; }}),
      "invalid '=' in base64 data");
  add("byte count past the data",
      file(kInline, {"Points",
                     [](Encoded& x) {
                       x.header.clear();
                       put(x.header, 1000, 4);
                     }}),
      "declares 1000 bytes but only");
  add("raw byte count past the data",
      file(kRaw, {"Points",
                  [](Encoded& x) {
                    x.header.clear();
                    put(x.header, 1u << 30, 4);
                  }}),
      "declares 1073741824 bytes but only");
  add("block sizes larger than the data",
      file(kInlineZlib, {"Points", [](Encoded& x) { x.header.replace(24, 8, u64(100000)); }}),
      "the zlib blocks are declared larger than the");
  add("huge block count",
      file(kRawZlib,
           {"Points", [](Encoded& x) { x.header.replace(0, 8, u64(uint64_t{1} << 40)); }}),
      "blocks, more than the data can hold");
  add("inflation beyond zlib's ratio",
      file(kInlineZlib, {"Points",
                         [](Encoded& x) {
                           x.header.clear();
                           for (uint64_t v : {uint64_t{1}, uint64_t{1} << 40, uint64_t{0},
                                              uint64_t{x.data.size()}})
                             put(x.header, v, 8);
                         }}),
      "compressed bytes can hold");
  add("block inflates to more than declared",
      file(kInlineZlib, {"Points", [](Encoded& x) { one_block_of(x, Bytes(96, 'a')); }}),
      "inflates to more than the 72 bytes declared");
  add("block inflates to fewer than declared",
      file(kInlineZlib, {"Points", [](Encoded& x) { one_block_of(x, Bytes(64, 'a')); }}),
      "inflates to 64 bytes, not the 72 declared");
  add("not zlib data",
      file(kRawZlib, {"Points",
                      [](Encoded& x) {
                        for (char& c : x.data) c = 'Z';
                      }}),
      "is not valid zlib data");
  add("truncated zlib block",
      file(kBase64Zlib, {"Points",
                         [](Encoded& x) {
                           one_block_of(x, Bytes(72, 'a'));
                           x.data.resize(x.data.size() - 3);
                           x.header.resize(24);
                           put(x.header, x.data.size(), 8);
                         }}),
      "is truncated");
  add("offset past the end",
      file(kRaw, {"Points", {}, {}, "format=\"appended\" offset=\"100000\""}),
      "offset 100000 is past the end of the appended data");
  add("negative offset", file(kRaw, {"Points", {}, {}, "format=\"appended\" offset=\"-1\""}),
      "non-negative integer offset");
  add("too few points",
      file(kInline, {"Points",
                     [](Encoded& x) {
                       x.data.resize(48);
                       x.header.clear();
                       put(x.header, 48, 4);
                     }}),
      "Points has 6 values where 9 are expected");
  add("not a whole number of values",
      file(kInline, {"Points",
                     [](Encoded& x) {
                       x.data.resize(71);
                       x.header.clear();
                       put(x.header, 71, 4);
                     }}),
      "not a whole number of Float64 values");
  add("nan point",
      file(kInline, {"Points",
                     [](Encoded& x) {
                       const double nan = std::nan("");
                       std::memcpy(&x.data[0], &nan, 8);
                     }}),
      "finite number");
  add("appended without AppendedData",
      triangle_file(kInline, {"Points", {}, {}, "format=\"appended\" offset=\"0\""}),
      "the file has no <AppendedData>");
  add("unknown type", triangle_file(kInline, {}, "Float128"),
      "unknown DataArray type \"Float128\"");
  const std::string float_connectivity = triangle_file(kInline, {}, "Float64", "Float32");
  cases.push_back({"float connectivity", float_connectivity,
                   line_of(float_connectivity, "connectivity"),
                   "connectivity needs an integer type, not Float32"});
  const std::string huge = triangle_file(
      kInline, {"connectivity", [](Encoded& x) { x.data[7] = '\x80'; }}, "Float64", "UInt64");
  cases.push_back({"UInt64 too large", huge, line_of(huge, "connectivity"), "too large"});
  return cases;
}

TEST(VtuEncodingFile, BrokenBinaryDataIsAnInputError) {
  for (const Broken& b : broken_binary_files()) expect_rejected(b);
}

TEST(VtuEncodingFile, BrokenFileAttributesAreInputErrors) {
  const std::string good = triangle_file(kRawZlib, {});
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expect_rejected({"big endian", with("LittleEndian", "BigEndian"), 2,
                   "big-endian VTK files are not supported"});
  expect_rejected(
      {"header type", with("UInt64", "UInt16"), 2, "header_type must be UInt32 or UInt64"});
  expect_rejected({"LZMA", with("vtkZLibDataCompressor", "vtkLZMADataCompressor"), 2,
                   "compressor vtkLZMADataCompressor is not supported"});
  const long appended = line_of(good, "<AppendedData");
  expect_rejected({"AppendedData not closed", with("</AppendedData>", ""), appended,
                   "not closed by </AppendedData>"});
  expect_rejected({"AppendedData encoding", with("encoding=\"raw\"", "encoding=\"hex\""), appended,
                   "encoding=\"raw\" or \"base64\""});
}

// Byte flips and cuts of compressed and appended files: read or InputError, nothing else.
TEST(VtuEncodingFile, MutatedBinaryFilesReadOrFailCleanly) {
  const VolumeMesh m = test::cube_tet_mesh();
  std::mt19937 rng(27);
  for (const Encoding& e : kEncodings) {
    const std::string base = mesh_file(m, e);
    for (int i = 0; i < 300; ++i) {
      std::string text = base;
      const size_t at = text.find("<Points") + rng() % (text.size() - text.find("<Points"));
      if (i % 5 == 4)
        text.erase(at, 1 + rng() % 16);
      else
        text[at] = static_cast<char>(rng());
      try {
        read_vtu_volume(TextSource("mutant.vtu", text));
      } catch (const InputError&) {
      }
    }
  }
}

// ---- the compressed writer ----

// A jittered grid of n^3 cubes, 6 tets each, in UTM-like coordinates: arrays of several zlib
// blocks.
VolumeMesh grid_mesh(int n) {
  VolumeMesh m;
  m.frame.origin = Vec3(512345, 4012345, -2500);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.vertices.emplace_back(i + jitter(rng), j + jitter(rng), k + jitter(rng));
  const int perms[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto corner = [&](int bits) {
          return id(i + (bits & 1), j + ((bits >> 1) & 1), k + (bits >> 2));
        };
        for (const auto& p : perms) {
          m.tets.push_back({corner(0), corner(p[0]), corner(p[0] + p[1]), corner(7)});
          m.tet_region.push_back(k < n / 2 ? 0 : 1);
        }
        if (k == 0) {
          m.triangles.push_back({corner(0), corner(2), corner(1)});
          m.triangle_surface.push_back(i % 3);
        }
      }
  m.region_names = {"region_0", "region_1"};
  m.surface_names = {"surface_0", "surface_1", "surface_2"};
  return m;
}

TEST(VtuWriter, CompressedVolumeMeshReadsBackExactly) {
  const VolumeMesh m = grid_mesh(12);  // 10368 tets: connectivity of 331776 bytes, 11 blocks
  std::ostringstream binary, ascii;
  write_vtu_volume(m, binary, 17);
  write_vtu_volume_ascii(m, ascii, 17);
  EXPECT_NE(binary.str().find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_EQ(binary.str().find("format=\"ascii\""), std::string::npos);
  EXPECT_LT(binary.str().size() * 3, ascii.str().size());
  const VolumeMesh from_binary = read_vtu_volume(TextSource("grid.vtu", binary.str()));
  expect_same_mesh(from_binary, m);  // Float64: exact
  expect_same_mesh(read_vtu_volume(TextSource("grid.vtu", ascii.str())), m, 1e-9);
  EXPECT_EQ(from_binary.region_names.size(), 2u);
  EXPECT_EQ(from_binary.surface_names.size(), 3u);
}

TEST(VtuWriter, CompressedModelReadsBackAsTheAsciiOne) {
  const StructuralModel model = build_model(test::lattice_box(4, true));
  std::ostringstream binary, ascii;
  write_vtu(model, binary, 17);
  write_vtu_ascii(model, ascii, 17);
  const SurfaceSoup a = read_vtu(TextSource("m.vtu", binary.str()));
  const SurfaceSoup b = read_vtu(TextSource("m.vtu", ascii.str()));
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_group, b.triangle_group);
  EXPECT_EQ(a.groups.size(), b.groups.size());
  // Through the file API too: the default .vtu output is the compressed one.
  test::ScratchDir dir;
  write_model(model, dir.file("box.vtu"));
  EXPECT_EQ(test::read_text(dir.file("box.vtu")), binary.str());
  EXPECT_EQ(read_model(dir.file("box.vtu")).num_triangles(), model.num_triangles());
}

// The test's decoder of base64 text made of padded parts.
Bytes unbase64(const std::string& s) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  Bytes out;
  uint32_t group = 0;
  int n = 0, pad = 0;
  for (char c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    pad += c == '=';
    group = (group << 6) | static_cast<uint32_t>(c == '=' ? 0 : std::strchr(digits, c) - digits);
    if (++n < 4) continue;
    for (int k = 0; k < 3 - pad; ++k) out += static_cast<char>(group >> (16 - 8 * k));
    n = pad = 0;
    group = 0;
  }
  return out;
}

// The test's decoder of an inline zlib array with a UInt64 header (VTK's layout).
Bytes decode_zlib_array(const std::string& text) {
  const Bytes b = unbase64(text);
  auto u64 = [&](size_t i) {
    uint64_t v = 0;
    for (int k = 7; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b.at(8 * i + k));
    return v;
  };
  const uint64_t blocks = u64(0), block = u64(1), last = u64(2);
  size_t at = 8 * (3 + blocks);
  Bytes out;
  for (uint64_t k = 0; k < blocks; ++k) {
    const uint64_t compressed = u64(3 + k);
    uLongf n = k + 1 == blocks && last > 0 ? last : block;
    Bytes o(n, '\0');
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(&o[0]), &n,
                         reinterpret_cast<const Bytef*>(b.data() + at), compressed),
              Z_OK);
    out += o.substr(0, n);
    at += compressed;
  }
  return out;
}

// The inline text of the DataArray called `name`.
std::string array_text(const std::string& file, const std::string& name) {
  const size_t tag = file.find("Name=\"" + name + "\"");
  const size_t begin = file.find('>', tag) + 1;
  return file.substr(begin, file.find('<', begin) - begin);
}

TEST(VtuWriter, CompressedArraysDecodeWithZlibAlone) {
  // The cube's boundary triangles (right isoceles) have quality 6S/(sqrt3 h p).
  const VolumeMesh m = test::cube_tet_mesh();
  std::ostringstream out;
  write_vtu_volume(m, out, 17);
  const Bytes quality = decode_zlib_array(array_text(out.str(), "quality"));
  ASSERT_EQ(quality.size(), 4 * (m.triangles.size() + m.tets.size()));
  float q0;
  std::memcpy(&q0, quality.data(), 4);
  const double s = 2.0, h = 2.0 * std::sqrt(2.0), p = 0.5 * (4.0 + h);
  EXPECT_NEAR(q0, 6.0 * s / (std::sqrt(3.0) * h * p), 1e-6);
  const Bytes points = decode_zlib_array(array_text(out.str(), "Points"));
  ASSERT_EQ(points.size(), 24 * m.vertices.size());
  double x;
  std::memcpy(&x, points.data() + 24 * 7, 8);
  EXPECT_EQ(x, m.vertices[7].x() + m.frame.origin.x());
}

// ---- files written by meshio ----

// An interpreter that imports meshio (Debian's first: a pyenv python3 may lack it), or "".
std::string meshio_python() {
  for (const char* python : {"/usr/bin/python3", "python3"})
    if (std::system((std::string(python) + " -c 'import meshio' >/dev/null 2>&1").c_str()) == 0)
      return python;
  return "";
}

std::string python_list(const std::vector<double>& v, int per_row) {
  std::string s = "[";
  char buffer[32];
  for (size_t i = 0; i < v.size(); ++i) {
    if (i % per_row == 0) s += "[";
    std::snprintf(buffer, sizeof buffer, "%.17g", v[i]);
    s += buffer;
    s += (i + 1) % per_row == 0 ? "]," : ",";
  }
  return s + "]";
}

// A script that writes the cube with meshio in every vtu flavour it has, and reads `ours`.
std::string meshio_script(const VolumeMesh& m) {
  std::vector<double> points, triangles, tets, surface, region;
  for (const Vec3& v : m.vertices)
    for (int k = 0; k < 3; ++k) points.push_back((v + m.frame.origin)[k]);
  for (const Triangle& t : m.triangles)
    triangles.insert(triangles.end(), {1.0 * t[0], 1.0 * t[1], 1.0 * t[2]});
  for (const Tetrahedron& t : m.tets)
    tets.insert(tets.end(), {1.0 * t[0], 1.0 * t[1], 1.0 * t[2], 1.0 * t[3]});
  for (int s : m.triangle_surface) surface.push_back(s);
  for (int r : m.tet_region) region.push_back(r);
  return "import sys, meshio, numpy as np\n"
         "points = np.array(" +
         python_list(points, 3) +
         ")\n"
         "cells = [('triangle', np.array(" +
         python_list(triangles, 3) +
         ", dtype=int)),\n"
         "         ('tetra', np.array(" +
         python_list(tets, 4) +
         ", dtype=int))]\n"
         "surface = [np.array(" +
         python_list(surface, 1) + ")[:, 0], -np.ones(" + std::to_string(m.tets.size()) +
         ", dtype=int)]\n"
         "region = [-np.ones(" +
         std::to_string(m.triangles.size()) + ", dtype=int), np.array(" + python_list(region, 1) +
         ")[:, 0]]\n"
         "mesh = meshio.Mesh(points, cells, cell_data={'surface': surface, 'region': region})\n"
         "for binary, compression, header in [(False, None, None), (True, None, None),\n"
         "        (True, 'zlib', None), (True, None, 'UInt64'), (True, 'zlib', 'UInt64')]:\n"
         "    name = 'meshio_%s_%s_%s.vtu' % (binary, compression, header)\n"
         "    try:\n"
         "        meshio.vtu.write(name, mesh, binary=binary, compression=compression,\n"
         "                         header_type=header)\n"
         "    except TypeError:  # a meshio without header_type\n"
         "        if header is None:\n"
         "            meshio.vtu.write(name, mesh, binary=binary, compression=compression)\n"
         "ours = meshio.read('ours.vtu')\n"
         "with open('ours.txt', 'w') as f:\n"
         "    f.write('%d %d %d\\n' % (len(ours.points), sum(len(c.data) for c in ours.cells),\n"
         "                            len(ours.cell_data['quality'])))\n";
}

TEST(VtuMeshio, ReadsWhatMeshioWritesAndMeshioReadsOurs) {
  const std::string python = meshio_python();
  if (python.empty()) GTEST_SKIP() << "meshio is not installed (Debian: python3-meshio)";
  const VolumeMesh m = test::cube_tet_mesh();
  test::ScratchDir dir;
  write_volume_mesh(m, dir.file("ours.vtu"));
  test::write_text(dir.file("write.py"), meshio_script(m));
  const std::string command = "cd '" + dir.path().string() + "' && " + python + " write.py";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  // meshio reads our compressed file: points, cells (in two blocks), cell data blocks.
  EXPECT_EQ(test::read_text(dir.file("ours.txt")), "8 18 2\n");
  int files = 0;
  for (const std::string& name : dir.listing()) {
    if (name.rfind("meshio_", 0) != 0) continue;
    SCOPED_TRACE(name);
    ++files;
    expect_same_mesh(read_volume_mesh(dir.file(name)), m, 1e-6);
  }
  EXPECT_GE(files, 3);
}

}  // namespace
}  // namespace voroseal
