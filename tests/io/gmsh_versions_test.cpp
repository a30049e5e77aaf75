// Gmsh MSH 2.2 and 4.1, ASCII and binary. A mesh written by hand in each of them reads the same
// as the MSH 4.1 ASCII our writer makes of it; broken binary files are refused with InputError;
// files that gmsh and meshio write, when they are installed, read the same in every version.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "io/gmsh_format.h"
#include "io/gmsh_reader.h"
#include "io/model_io.h"
#include "io/tag_names.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// ---- a mesh given as Gmsh elements, and writers of the versions under test ----

struct Element {
  int type;      // 15 point, 1 line, 2 triangle, 3 quadrangle, 4 tetrahedron
  int physical;  // 0: none
  int entity;
  std::vector<long long> nodes;  // node tags, 1-based
};

struct GmshMesh {
  std::vector<Vec3> nodes;  // tag = index + 1
  std::vector<Element> elements;
  std::vector<std::tuple<int, int, std::string>> names;  // dim, physical tag, name
};

int dim_of(int type) {
  return type == 15 ? 0 : type == 1 ? 1 : type == 4 ? 3 : 2;
}

// Entity tags differ from physical tags (so that the reader must prefer the physical tag); a
// point and a line lead the elements (so that the reader must drop them).
GmshMesh gmsh_mesh(const VolumeMesh& m) {
  GmshMesh g;
  for (const Vec3& v : m.vertices) g.nodes.push_back(v + m.frame.origin);
  g.elements.push_back({15, 0, 1, {1}});
  g.elements.push_back({1, 0, 1, {1, 2}});
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const int s = m.triangle_surface[f];
    const Triangle& t = m.triangles[f];
    g.elements.push_back({2, s + 1, s + 101, {t[0] + 1, t[1] + 1, t[2] + 1}});
  }
  for (size_t k = 0; k < m.tets.size(); ++k) {
    const int r = m.tet_region[k];
    const Tetrahedron& t = m.tets[k];
    g.elements.push_back({4, r + 1, r + 201, {t[0] + 1, t[1] + 1, t[2] + 1, t[3] + 1}});
  }
  for (size_t s = 0; s < m.surface_names.size(); ++s)
    g.names.emplace_back(2, static_cast<int>(s) + 1, m.surface_names[s]);
  for (size_t r = 0; r < m.region_names.size(); ++r)
    g.names.emplace_back(3, static_cast<int>(r) + 1, m.region_names[r]);
  return g;
}

// Text and little-endian binary values.
class Bytes {
 public:
  Bytes& text(const std::string& s) {
    out_ += s;
    return *this;
  }
  Bytes& i32(int32_t v) { return raw(static_cast<uint32_t>(v), 4); }
  Bytes& size(uint64_t v, size_t bytes) { return raw(v, bytes); }
  Bytes& f64(double v) {
    uint64_t u = 0;
    std::memcpy(&u, &v, 8);
    return raw(u, 8);
  }
  const std::string& str() const { return out_; }

 private:
  Bytes& raw(uint64_t v, size_t bytes) {
    for (size_t k = 0; k < bytes; ++k) out_ += static_cast<char>((v >> (8 * k)) & 0xff);
    return *this;
  }
  std::string out_;
};

std::string real(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

void header(Bytes& b, const GmshMesh& g, const std::string& version, bool binary,
            size_t size_bytes = 8) {
  b.text("$MeshFormat\n" + version + (binary ? " 1 " : " 0 ") + std::to_string(size_bytes) + "\n");
  if (binary) b.i32(1).text("\n");
  b.text("$EndMeshFormat\n$PhysicalNames\n" + std::to_string(g.names.size()) + "\n");
  for (const auto& [dim, tag, name] : g.names)
    b.text(std::to_string(dim) + " " + std::to_string(tag) + " \"" + name + "\"\n");
  b.text("$EndPhysicalNames\n");
}

std::string msh22(const GmshMesh& g, bool binary) {
  Bytes b;
  header(b, g, "2.2", binary);
  b.text("$Comments\nskipped\n$EndComments\n");
  b.text("$Nodes\n" + std::to_string(g.nodes.size()) + "\n");
  for (size_t v = 0; v < g.nodes.size(); ++v) {
    const Vec3& p = g.nodes[v];
    if (binary)
      b.i32(static_cast<int32_t>(v + 1)).f64(p.x()).f64(p.y()).f64(p.z());
    else
      b.text(std::to_string(v + 1) + " " + real(p.x()) + " " + real(p.y()) + " " + real(p.z()) +
             "\n");
  }
  b.text(binary ? "\n$EndNodes\n" : "$EndNodes\n");
  b.text("$Elements\n" + std::to_string(g.elements.size()) + "\n");
  for (size_t e = 0; e < g.elements.size(); ++e) {
    const Element& el = g.elements[e];
    if (binary) {
      b.i32(el.type).i32(1).i32(2);  // a block of one element: type, count, number of tags
      b.i32(static_cast<int32_t>(e + 1)).i32(el.physical).i32(el.entity);
      for (long long n : el.nodes) b.i32(static_cast<int32_t>(n));
    } else {
      std::string line = std::to_string(e + 1) + " " + std::to_string(el.type) + " 2 " +
                         std::to_string(el.physical) + " " + std::to_string(el.entity);
      for (long long n : el.nodes) line += " " + std::to_string(n);
      b.text(line + "\n");
    }
  }
  b.text(binary ? "\n$EndElements\n" : "$EndElements\n");
  return b.str();
}

// Runs of consecutive elements of one entity and type: the element blocks of MSH 4.1.
std::vector<std::pair<size_t, size_t>> element_blocks(const GmshMesh& g) {
  std::vector<std::pair<size_t, size_t>> blocks;  // first, end
  for (size_t e = 0; e < g.elements.size(); ++e) {
    const Element& a = g.elements[e];
    if (!blocks.empty()) {
      const Element& b = g.elements[blocks.back().first];
      if (a.type == b.type && a.entity == b.entity) {
        blocks.back().second = e + 1;
        continue;
      }
    }
    blocks.emplace_back(e, e + 1);
  }
  return blocks;
}

void entities41_binary(Bytes& b, const GmshMesh& g, size_t sz) {
  std::map<std::pair<int, int>, int> entities;  // (dim, tag) -> physical
  for (const Element& e : g.elements) entities[{dim_of(e.type), e.entity}] = e.physical;
  b.text("$Entities\n");
  for (int dim = 0; dim < 4; ++dim) {
    size_t n = 0;
    for (const auto& [key, physical] : entities) n += key.first == dim;
    b.size(n, sz);
  }
  for (const auto& [key, physical] : entities) {
    b.i32(key.second);
    for (int k = 0; k < (key.first == 0 ? 3 : 6); ++k) b.f64(0.0);
    b.size(physical ? 1 : 0, sz);
    if (physical) b.i32(physical);
    if (key.first > 0) b.size(1, sz).i32(-1);  // one bounding entity, ignored
  }
  b.text("\n$EndEntities\n");
}

std::string msh41_binary(const GmshMesh& g, size_t sz = 8) {
  Bytes b;
  header(b, g, "4.1", true, sz);
  entities41_binary(b, g, sz);
  const size_t nv = g.nodes.size();
  b.text("$Nodes\n").size(1, sz).size(nv, sz).size(1, sz).size(nv, sz);
  b.i32(3).i32(201).i32(0).size(nv, sz);
  for (size_t v = 0; v < nv; ++v) b.size(v + 1, sz);
  for (const Vec3& p : g.nodes) b.f64(p.x()).f64(p.y()).f64(p.z());
  b.text("\n$EndNodes\n$Elements\n");
  const auto blocks = element_blocks(g);
  const size_t ne = g.elements.size();
  b.size(blocks.size(), sz).size(ne, sz).size(1, sz).size(ne, sz);
  for (const auto& [first, end] : blocks) {
    const Element& a = g.elements[first];
    b.i32(dim_of(a.type)).i32(a.entity).i32(a.type).size(end - first, sz);
    for (size_t e = first; e < end; ++e) {
      b.size(e + 1, sz);
      for (long long n : g.elements[e].nodes) b.size(static_cast<uint64_t>(n), sz);
    }
  }
  b.text("\n$EndElements\n");
  return b.str();
}

// ---- the meshes ----

// The 12 triangles of the box [0, 2]^3 + origin: "bottom" (z = min, 2 triangles) and "walls".
VolumeMesh box_surfaces() {
  VolumeMesh m = test::cube_tet_mesh();
  m.tets.clear();
  m.tet_region.clear();
  m.region_names.clear();
  for (int& s : m.triangle_surface) s = s == 4 ? 0 : 1;
  std::vector<Triangle> sorted;
  std::vector<int> surface;
  for (int s = 0; s < 2; ++s)
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.triangle_surface[f] == s) {
        sorted.push_back(m.triangles[f]);
        surface.push_back(s);
      }
  m.triangles = sorted;
  m.triangle_surface = surface;
  m.surface_names = {"bottom", "walls"};
  return m;
}

std::string writer_text(const VolumeMesh& m) {
  std::ostringstream out;
  write_msh_volume(m, out, 17);
  return out.str();
}

void expect_same_soup(const SurfaceSoup& a, const SurfaceSoup& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_group, b.triangle_group);
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (size_t k = 0; k < a.groups.size(); ++k) EXPECT_EQ(a.groups[k].name, b.groups[k].name);
}

void expect_same_volume(const VolumeMesh& a, const VolumeMesh& b, double tolerance = 0) {
  EXPECT_EQ(a.frame.origin, b.frame.origin);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (size_t v = 0; v < a.vertices.size(); ++v)
    EXPECT_LE((a.vertices[v] - b.vertices[v]).norm(), tolerance) << "vertex " << v;
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.tet_region, b.tet_region);
  EXPECT_EQ(a.region_names, b.region_names);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_surface, b.triangle_surface);
  EXPECT_EQ(a.surface_names, b.surface_names);
}

struct Variant {
  std::string name;
  std::string text;
};

std::vector<Variant> variants(const VolumeMesh& m) {
  const GmshMesh g = gmsh_mesh(m);
  return {{"2.2 ASCII", msh22(g, false)},
          {"2.2 binary", msh22(g, true)},
          {"4.1 binary", msh41_binary(g)},
          {"4.1 binary, 4-byte size_t", msh41_binary(g, 4)}};
}

// ---- every version reads as MSH 4.1 ASCII ----

TEST(GmshVersions, BoxOfTrianglesReadsAsTheWritersMsh41) {
  const VolumeMesh m = box_surfaces();
  test::ScratchDir dir;
  test::write_text(dir.file("ref.msh"), writer_text(m));
  const SurfaceSoup ref = read_soup(dir.file("ref.msh"));
  ASSERT_EQ(ref.triangles.size(), 12u);
  ASSERT_EQ(ref.groups.size(), 2u);
  EXPECT_EQ(ref.groups[0].name, "bottom");
  for (const Variant& v : variants(m)) {
    SCOPED_TRACE(v.name);
    test::write_text(dir.file("v.msh"), v.text);
    expect_same_soup(read_soup(dir.file("v.msh")), ref);
    EXPECT_EQ(read_model(dir.file("v.msh")).parts.size(),
              read_model(dir.file("ref.msh")).parts.size());
  }
}

TEST(GmshVersions, TetsReadAsTheWritersMsh41) {
  const VolumeMesh m = test::cube_tet_mesh();
  test::ScratchDir dir;
  test::write_text(dir.file("ref.msh"), writer_text(m));
  const VolumeMesh ref = read_volume_mesh(dir.file("ref.msh"));
  ASSERT_EQ(ref.tets.size(), 6u);
  EXPECT_EQ(ref.region_names, (std::vector<std::string>{"lower", "upper"}));
  for (const Variant& v : variants(m)) {
    SCOPED_TRACE(v.name);
    test::write_text(dir.file("v.msh"), v.text);
    expect_same_volume(read_volume_mesh(dir.file("v.msh")), ref);
  }
}

// The MSH 2.2 tag rules: the physical tag (first) when not 0, else the entity tag (second);
// further tags (partitions) ignored; quadrangles split; other sections skipped.
TEST(GmshVersions, Msh22TagsQuadsAndSections) {
  const std::string text =
      "$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n"
      "$PhysicalNames\n1\n2 5 \"five\"\n$EndPhysicalNames\n"
      "$Nodes\n5\n10 0 0 0\n20 1 0 0\n30 1 1 0\n40 0 1 0\n50 0 0 1\n$EndNodes\n"
      "$NodeData\n1\n\"x\"\n$EndNodeData\n"
      "$Elements\n5\n"
      "1 15 2 0 1 10\n"
      "2 1 0 10 20\n"
      "3 3 3 5 1 7 10 20 30 40\n"  // quadrangle, physical 5, partition 7
      "4 2 2 0 3 10 20 50\n"       // no physical: entity 3
      "5 2 1 5 20 30 50\n"         // physical only
      "$EndElements\n";
  const SurfaceSoup s = read_msh(TextSource("t.msh", text));
  ASSERT_EQ(s.points.size(), 5u);
  ASSERT_EQ(s.triangles.size(), 4u);
  EXPECT_EQ(s.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(s.triangles[1], (Triangle{0, 2, 3}));
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[0].name, "surface_2");  // entity 3, no physical name for tag 3
  EXPECT_EQ(s.groups[1].name, "five");
  EXPECT_EQ(s.triangle_group, (std::vector<int>{1, 1, 0, 1}));
}

// A MSH 4.1 entity without a physical group gives its own tag (as in ASCII).
TEST(GmshVersions, Msh41BinaryEntityTagWithoutPhysical) {
  VolumeMesh m = test::cube_tet_mesh();
  GmshMesh g = gmsh_mesh(m);
  for (Element& e : g.elements)
    if (e.type == 4) e.physical = 0;
  const VolumeMesh v = read_msh_volume(TextSource("t.msh", msh41_binary(g)));
  EXPECT_EQ(v.tet_region, (std::vector<int>{200, 200, 200, 201, 201, 201}));
  ASSERT_EQ(v.region_names.size(), 202u);
  EXPECT_EQ(v.region_names[200], "region_200");
}

// ---- broken binary files ----

// Reads `text` as a volume mesh; returns the error message ("" when it reads).
std::string volume_error(const std::string& text) {
  try {
    read_msh_volume(TextSource("broken.msh", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, const std::string& message) {
  const std::string error = volume_error(text);
  EXPECT_NE(error.find(message), std::string::npos) << "error: '" << error << "'";
}

// Overwrites the little-endian value of `bytes` bytes at `at`.
std::string patched(std::string text, size_t at, uint64_t value, size_t bytes) {
  for (size_t k = 0; k < bytes; ++k) text[at + k] = static_cast<char>((value >> (8 * k)) & 0xff);
  return text;
}

size_t after(const std::string& text, const std::string& marker) {
  const size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return at + marker.size();
}

TEST(GmshVersions, EveryTruncationIsAnInputError) {
  for (const Variant& v : variants(test::cube_tet_mesh())) {
    SCOPED_TRACE(v.name);
    EXPECT_EQ(volume_error(v.text), "");
    // Without its last newline the file is still whole.
    for (size_t n = 0; n + 1 < v.text.size(); ++n)
      EXPECT_NE(volume_error(v.text.substr(0, n)), "") << "cut at " << n;
  }
}

TEST(GmshVersions, Msh41BinaryCountsAndTags) {
  const std::string text = msh41_binary(gmsh_mesh(test::cube_tet_mesh()));
  const size_t nodes = after(text, "$Nodes\n"), elements = after(text, "$Elements\n");
  const size_t node_block = nodes + 32, element_block = elements + 32;
  const uint64_t huge = uint64_t{1} << 60;
  expect_error(patched(text, nodes + 8, huge, 8), "byte " + std::to_string(nodes + 8) +
                                                      ": number of nodes = 1152921504606846976 "
                                                      "is more than the rest of the file can hold");
  expect_error(patched(text, node_block + 12, huge, 8), "number of nodes in block");
  expect_error(patched(text, node_block + 12, 9, 8), "more nodes than declared");
  expect_error(patched(text, nodes + 8, 9, 8), "declares 9 nodes but its blocks hold 8");
  expect_error(patched(text, elements + 8, ~uint64_t{0}, 8), "number of elements =");
  expect_error(patched(text, element_block + 12, huge, 8), "number of elements in block");
  expect_error(patched(text, element_block + 8, 9, 4), "unsupported element type 9");
  expect_error(patched(text, node_block + 20, 0, 8), "node tag 0 out of range");
  expect_error(patched(text, node_block + 20, ~uint64_t{0}, 8), "out of range");
  expect_error(patched(text, node_block + 28, 1, 8), "duplicate node tag 1");
  expect_error(patched(text, after(text, "$Entities\n"), huge, 8), "number of entities");
  // Blocks of a point (20 + 16 bytes) and a line (20 + 24), whose nodes are not looked up,
  // then of triangles: the first node of the first triangle.
  const size_t node_tag = element_block + 36 + 44 + 20 + 8;
  expect_error(patched(text, node_tag, 99, 8),
               "byte " + std::to_string(node_tag) + ": element refers to unknown node 99");
  expect_error(patched(text, node_tag, ~uint64_t{0}, 8), "unknown node 18446744073709551615");
  expect_error(patched(text, node_tag, 0x3ff0000000000000, 8), "unknown node");
}

TEST(GmshVersions, Msh22BinaryCountsAndTags) {
  const std::string text = msh22(gmsh_mesh(test::cube_tet_mesh()), true);
  const size_t nodes = after(text, "$Nodes\n8\n"), elements = after(text, "$Elements\n");
  std::string more = text;
  more.replace(nodes - 2, 1, "99");
  expect_error(more, "number of nodes = 99 is more than the rest of the file can hold");
  expect_error(patched(text, nodes + 28, 1, 4), "duplicate node tag 1");
  const size_t first = after(text, "$Elements\n20\n");
  ASSERT_EQ(first, elements + 3);
  expect_error(patched(text, first + 4, 1 << 30, 4), "more elements than declared");
  expect_error(patched(text, first + 4, -1, 4), "negative count");
  expect_error(patched(text, first + 8, 1 << 30, 4), "number of elements in block");
  expect_error(patched(text, first, 11, 4), "unsupported element type 11");
  // Elements: point (12 + 16 bytes), line (12 + 20), then the first triangle: its first node.
  const size_t triangle = first + 28 + 32 + 12;
  expect_error(patched(text, triangle + 12, 99, 4),
               "byte " + std::to_string(triangle + 12) + ": element refers to unknown node 99");
  expect_error(patched(patched(text, triangle + 4, 0, 4), triangle + 8, 0, 4),
               "no positive physical or entity tag");
  expect_error(patched(text, triangle + 4, 1 << 24, 4), "physical tag 16777216 out of range");
}

TEST(GmshVersions, FormatLine) {
  const std::string text = msh41_binary(gmsh_mesh(test::cube_tet_mesh()));
  const size_t one = after(text, "4.1 1 8\n");
  expect_error(patched(text, one, 0x01000000, 4), "big-endian binary .msh files are not supported");
  expect_error(patched(text, one, 2, 4), "expected the binary integer 1");
  std::string other = text;
  expect_error(other.replace(one - 8, 7, "4.0 1 8"), "only MSH versions 4.1 and 2.2");
  other = text;
  expect_error(other.replace(one - 8, 7, "4.1 1 2"), "data size 2 is not supported");
  other = text;
  expect_error(other.replace(one - 8, 7, "4.1 2 8"), "file type must be 0 (ASCII) or 1");
  const std::string ascii41 = writer_text(test::cube_tet_mesh());
  other = ascii41;
  other.replace(after(ascii41, "$MeshFormat\n"), 3, "2.2");
  expect_error(other, "broken.msh:15: $Entities is a MSH 4 section, but the format line says 2.2");
  const std::string ascii22 = msh22(gmsh_mesh(test::cube_tet_mesh()), false);
  other = ascii22;
  expect_error(other.replace(after(ascii22, "2.2 0 8\n") - 8, 7, "2.2 1 4"),
               "binary MSH 2.2 with data size 4 is not supported (8)");
}

// Every byte of the binary files replaced by a few values: the read succeeds or throws
// InputError, and never crashes, hangs or allocates beyond the file.
TEST(GmshVersions, CorruptBytesAreInputErrorsOrRead) {
  const unsigned char values[] = {0x00, 0x0a, 0x80, 0xff};
  for (const Variant& v : variants(test::cube_tet_mesh())) {
    if (v.name == "2.2 ASCII") continue;
    SCOPED_TRACE(v.name);
    for (size_t at = 0; at < v.text.size(); ++at)
      for (unsigned char c : values) {
        std::string t = v.text;
        t[at] = static_cast<char>(c);
        try {
          read_msh_volume(TextSource("c.msh", t));
        } catch (const InputError&) {
        }
      }
  }
}

// ---- files written by gmsh and meshio (skipped when they are not installed) ----

bool runs(const std::string& command) {
  return std::system((command + " >/dev/null 2>&1").c_str()) == 0;
}

// The first meshio-capable Python, or "".
std::string python_with_meshio() {
  for (const char* python : {"/usr/bin/python3", "python3"})
    if (runs(std::string(python) + " -c 'import meshio'")) return python;
  return "";
}

TEST(GmshVersions, FilesWrittenByGmsh) {
  if (!runs("command -v gmsh")) GTEST_SKIP() << "gmsh is not installed";
  test::ScratchDir dir;
  test::write_text(dir.file("cube.geo"),
                   "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                   "Physical Volume(\"rock\", 5) = {1};\nPhysical Surface(\"top\", 3) = {6};\n"
                   "Physical Surface(\"sides\", 4) = {1, 2, 3, 4, 5};\nMesh.MeshSizeMax = 0.5;\n");
  const std::string q = "'" + dir.path().string() + "/";
  ASSERT_TRUE(runs("gmsh -3 " + q + "cube.geo' -format msh41 -o " + q + "mesh.msh'"));
  // One mesh saved in every version by the same gmsh code.
  const std::vector<std::pair<std::string, std::string>> formats = {
      {"41.msh", "-format msh41"},
      {"41b.msh", "-format msh41 -bin"},
      {"22.msh", "-format msh22"},
      {"22b.msh", "-format msh22 -bin"}};
  for (const auto& [name, options] : formats)
    ASSERT_TRUE(runs("gmsh " + q + "mesh.msh' -save " + options + " -o " + q + name + "'"));
  const VolumeMesh ref = read_volume_mesh(dir.file("41.msh"));
  EXPECT_GT(ref.tets.size(), 20u);
  ASSERT_EQ(ref.region_names.size(), 5u);
  EXPECT_EQ(ref.region_names[4], "rock");
  EXPECT_EQ(std::set<int>(ref.tet_region.begin(), ref.tet_region.end()), std::set<int>{4});
  EXPECT_EQ(std::set<int>(ref.triangle_surface.begin(), ref.triangle_surface.end()),
            (std::set<int>{2, 3}));
  EXPECT_EQ(ref.surface_names[2], "top");
  for (const auto& [name, options] : formats) {
    SCOPED_TRACE(name);
    expect_same_volume(read_volume_mesh(dir.file(name)), ref, 1e-12);
  }
}

// A model's .msh: one physical group per surface ("<kind>:<name>"), one entity per piece (a
// part), the pieces named in $VorosealPieces; read back, parts, surfaces and kinds are the same.
TEST(GmshVersions, ModelGroupsAreSurfacesAndItsPiecesKeepTheirNames) {
  SurfaceSoup soup = test::lattice_box(4, true);
  soup.groups[0].kind = SurfaceKind::Boundary;
  const StructuralModel m = build_model(soup);
  ASSERT_GT(m.parts.size(), m.interfaces.size());  // some surface has several pieces
  test::ScratchDir dir;
  const std::string path = dir.file("model.msh");
  write_model(m, path);
  const MshData d = parse_msh(TextSource(path, test::read_text(path)));
  std::set<std::string> groups, expected_groups, pieces, part_names;
  for (const auto& [key, name] : d.physical_names)
    if (key.first == 2) groups.insert(name);
  for (const Interface& i : m.interfaces)
    expected_groups.insert(kind_prefixed_name(i.kind, i.name));
  EXPECT_EQ(groups, expected_groups);
  for (const auto& [entity, name] : d.piece_names) pieces.insert(name);
  for (const SurfacePart& p : m.parts) part_names.insert(p.name);
  EXPECT_EQ(pieces, part_names);
  const StructuralModel back = read_model(path);
  std::set<std::string> back_parts;
  for (const SurfacePart& p : back.parts) back_parts.insert(p.name);
  EXPECT_EQ(back_parts, part_names);
  ASSERT_EQ(back.interfaces.size(), m.interfaces.size());
  std::set<std::pair<std::string, SurfaceKind>> kinds, back_kinds;
  for (const Interface& i : m.interfaces) kinds.insert({i.name, i.kind});
  for (const Interface& i : back.interfaces) back_kinds.insert({i.name, i.kind});
  EXPECT_EQ(back_kinds, kinds);
  EXPECT_EQ(back.regions.size(), m.regions.size());

  // meshio (when installed) skips the pieces' section and sees one group per surface.
  const std::string python = python_with_meshio();
  if (python.empty()) GTEST_SKIP() << "python3 with meshio is not installed";
  test::write_text(dir.file("read.py"),
                   "import sys, meshio\n"
                   "m = meshio.read(sys.argv[1])\n"
                   "tags = set()\n"
                   "for block, tag in zip(m.cells, m.cell_data['gmsh:physical']):\n"
                   "    if block.type == 'triangle': tags.update(int(t) for t in tag)\n"
                   "names = [n for n, (t, dim) in m.field_data.items() if dim == 2]\n"
                   "open(sys.argv[2], 'w').write(f'{len(tags)} {len(names)}')\n");
  ASSERT_TRUE(
      runs(python + " '" + dir.file("read.py") + "' '" + path + "' '" + dir.file("out.txt") + "'"));
  const std::string expected =
      std::to_string(m.interfaces.size()) + " " + std::to_string(m.interfaces.size());
  EXPECT_EQ(test::read_text(dir.file("out.txt")), expected);
}

TEST(GmshVersions, FilesWrittenByMeshio) {
  const std::string python = python_with_meshio();
  if (python.empty()) GTEST_SKIP() << "python3 with meshio is not installed";
  test::ScratchDir dir;
  test::write_text(
      dir.file("write.py"),
      "import sys, meshio, numpy as np\n"
      "d = sys.argv[1]\n"
      "points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)\n"
      "cells = [('triangle', np.array([[0, 1, 2], [0, 1, 3]])), ('tetra', np.array([[0, 1, 2, "
      "3]]))]\n"
      "m = meshio.Mesh(points, cells, point_data={'gmsh:dim_tags': np.array([[3, 1]] * 5)},\n"
      "    cell_data={'gmsh:physical': [np.array([1, 2]), np.array([1])],\n"
      "               'gmsh:geometrical': [np.array([1, 2]), np.array([1])]},\n"
      "    field_data={'top': np.array([1, 2]), 'side': np.array([2, 2]),\n"
      "                'rock': np.array([1, 3])})\n"
      "for name, fmt, binary in [('22', 'gmsh22', False), ('22b', 'gmsh22', True),\n"
      "                          ('41', 'gmsh', False), ('41b', 'gmsh', True)]:\n"
      "    meshio.write(d + '/' + name + '.msh', m, file_format=fmt, binary=binary)\n");
  ASSERT_TRUE(runs(python + " '" + dir.file("write.py") + "' '" + dir.path().string() + "'"));
  const VolumeMesh v22 = read_volume_mesh(dir.file("22.msh"));
  ASSERT_EQ(v22.tets.size(), 1u);
  EXPECT_EQ(v22.triangle_surface, (std::vector<int>{0, 1}));
  EXPECT_EQ(v22.surface_names, (std::vector<std::string>{"top", "side"}));
  EXPECT_EQ(v22.region_names, (std::vector<std::string>{"rock"}));
  expect_same_volume(read_volume_mesh(dir.file("22b.msh")), v22);
  // meshio's MSH 4.1 puts the triangles in an entity it does not declare: no physical tag.
  const VolumeMesh v41 = read_volume_mesh(dir.file("41.msh"));
  EXPECT_EQ(v41.tets, v22.tets);
  EXPECT_EQ(v41.triangles, v22.triangles);
  expect_same_volume(read_volume_mesh(dir.file("41b.msh")), v41);
}

}  // namespace
}  // namespace voroseal
