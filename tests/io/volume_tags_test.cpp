// Named tags of volume meshes: one id per input surface with its name and kind, the pieces of
// each surface, contact lines as edges and corners as points, in every volume format and back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "io/tag_names.h"
#include "io/vtk_format.h"
#include "tests/io/io_test_util.h"

namespace voroseal {
namespace {

using Point = std::array<double, 3>;
Point key(const VolumeMesh& m, int v) {
  const Vec3 p = m.vertices[v] + m.frame.origin;
  return {p.x(), p.y(), p.z()};
}

// The cube of cube_tet_mesh() tagged like a model: its 6 faces are the pieces (parts) of 3
// surfaces of different kinds (a name with XML specials, one with a colon; .msh names cannot
// hold '"'), its 12
// edges contacts grouped by the surfaces meeting there, its 8 vertices corners.
VolumeMesh tagged_cube() {
  VolumeMesh m = test::cube_tet_mesh();
  m.triangle_part = m.triangle_surface;  // faces xmin xmax ymin ymax zmin zmax
  m.part_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  const int surface_of_face[6] = {0, 0, 1, 1, 2, 2};
  for (int& s : m.triangle_surface) s = surface_of_face[s];
  m.surface_names = {"west & east <sides>", "south:north", "H1"};
  m.surface_kinds = {SurfaceKind::Boundary, SurfaceKind::Unknown, SurfaceKind::Horizon};
  // Cube edges (vertex bit 0: x, 1: y, 2: z): an edge along axis a lies on the two faces of the
  // two other axes, so its contact is the pair of those surfaces.
  std::map<std::set<int>, int> contact_id;
  for (int v = 0; v < 8; ++v)
    for (int axis = 0; axis < 3; ++axis) {
      if (v & (1 << axis)) continue;
      m.edges.push_back({v, v | (1 << axis)});
      std::set<int> surfaces;
      for (int other = 0; other < 3; ++other)
        if (other != axis) surfaces.insert(other);
      const auto [it, added] = contact_id.emplace(surfaces, static_cast<int>(contact_id.size()));
      m.edge_contact.push_back(it->second);
    }
  m.contact_names = {"south:north+H1", "west & east <sides>+H1", "west & east <sides>+south:north"};
  for (int v = 0; v < 8; ++v) {
    m.corners.push_back(v);
    m.corner_id.push_back(v == 0 ? 1 : 0);  // two corner ids, to see them kept apart
  }
  m.corner_names = {"all three", "origin"};
  return m;
}

// Elements as file points with their id, sorted (writers may reorder elements).
template <size_t N>
std::vector<std::tuple<std::array<Point, N>, int>> keyed(const VolumeMesh& m,
                                                         const std::vector<std::array<int, N>>& e,
                                                         const std::vector<int>& ids) {
  std::vector<std::tuple<std::array<Point, N>, int>> out;
  for (size_t k = 0; k < e.size(); ++k) {
    std::array<Point, N> p;
    for (size_t i = 0; i < N; ++i) p[i] = key(m, e[k][i]);
    out.emplace_back(p, k < ids.size() ? ids[k] : -1);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::tuple<Point, int>> keyed_corners(const VolumeMesh& m) {
  std::vector<std::tuple<Point, int>> out;
  for (size_t k = 0; k < m.corners.size(); ++k)
    out.emplace_back(key(m, m.corners[k]), m.corner_id[k]);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<SurfaceKind> kinds(const VolumeMesh& m) {
  std::vector<SurfaceKind> out;
  for (size_t s = 0; s < m.surface_names.size(); ++s) out.push_back(m.surface_kind(int(s)));
  return out;
}

void expect_same_tags(const VolumeMesh& read, const VolumeMesh& written, bool parts) {
  EXPECT_EQ(read.surface_names, written.surface_names);
  EXPECT_EQ(kinds(read), kinds(written));
  EXPECT_EQ(read.region_names, written.region_names);
  EXPECT_EQ(read.contact_names, written.contact_names);
  EXPECT_EQ(read.corner_names, written.corner_names);
  EXPECT_EQ(keyed(read, read.triangles, read.triangle_surface),
            keyed(written, written.triangles, written.triangle_surface));
  EXPECT_EQ(keyed(read, read.tets, read.tet_region),
            keyed(written, written.tets, written.tet_region));
  ASSERT_EQ(read.edges.size(), written.edges.size());
  EXPECT_EQ(keyed(read, read.edges, read.edge_contact),
            keyed(written, written.edges, written.edge_contact));
  ASSERT_EQ(read.corners.size(), written.corners.size());
  EXPECT_EQ(keyed_corners(read), keyed_corners(written));
  if (parts) {
    EXPECT_EQ(keyed(read, read.triangles, read.triangle_part),
              keyed(written, written.triangles, written.triangle_part));
  }
}

class VolumeTags : public ::testing::TestWithParam<std::string> {};

TEST_P(VolumeTags, RoundTripNamesKindsPiecesContactsAndCorners) {
  const std::string ext = GetParam();
  test::ScratchDir dir;
  const VolumeMesh m = tagged_cube();
  ASSERT_EQ(m.edges.size(), 12u);
  ASSERT_EQ(m.contact_names.size(), 3u);
  const std::string path = dir.file("cube" + ext);
  write_volume_mesh(m, path);
  const VolumeMesh read = read_volume_mesh(path);
  // Medit holds no pieces; .msh their ids (entities), .vtu ids and names.
  expect_same_tags(read, m, ext != ".mesh");
  if (ext == ".vtu") {
    EXPECT_EQ(read.part_names, m.part_names);
  }
  if (ext == ".mesh") {
    EXPECT_EQ(dir.listing(), (std::vector<std::string>{"cube.mesh", "cube.mesh.json"}));
  }
}

INSTANTIATE_TEST_SUITE_P(VolumeFormats, VolumeTags, ::testing::Values(".mesh", ".vtu", ".msh"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(VolumeTags, AsciiVtuReadsLikeTheCompressedOne) {
  std::ostringstream out;
  const VolumeMesh m = tagged_cube();
  write_vtu_volume_ascii(m, out, 17);
  const VolumeMesh read = read_vtu_volume(TextSource{"cube.vtu", out.str()});
  expect_same_tags(read, m, true);
}

TEST(VolumeTags, MshGroupsEveryPieceOfASurfaceUnderOneNamedPhysicalGroup) {
  test::ScratchDir dir;
  write_volume_mesh(tagged_cube(), dir.file("cube.msh"));
  const std::string text = test::read_text(dir.file("cube.msh"));
  const std::string names = text.substr(
      text.find("$PhysicalNames"), text.find("$EndPhysicalNames") - text.find("$PhysicalNames"));
  // 2 corner ids, 3 contacts, 3 surfaces (not 6 faces), 2 regions.
  EXPECT_NE(names.find("$PhysicalNames\n10\n"), std::string::npos) << names;
  EXPECT_NE(names.find("2 3 \"horizon:H1\""), std::string::npos) << names;
  EXPECT_NE(names.find("2 2 \"unknown:south:north\""), std::string::npos) << names;
  EXPECT_NE(names.find("1 1 \"contact:south:north+H1\""), std::string::npos) << names;
  EXPECT_NE(names.find("0 2 \"corner:origin\""), std::string::npos) << names;
  // One surface entity per face, each in its surface's group: "tag box... 1 physical 0".
  const std::string entities =
      text.substr(text.find("$Entities"), text.find("$Nodes") - text.find("$Entities"));
  EXPECT_NE(entities.find("$Entities\n8 3 6 2\n"), std::string::npos) << entities;
}

TEST(VolumeTags, KindPrefixesSplitOnlyOnKindWords) {
  SurfaceKind kind;
  std::string name;
  split_kind_prefixed_name("fault:F1", kind, name);
  EXPECT_EQ(kind, SurfaceKind::Fault);
  EXPECT_EQ(name, "F1");
  split_kind_prefixed_name("unknown:a:b", kind, name);
  EXPECT_EQ(kind, SurfaceKind::Unknown);
  EXPECT_EQ(name, "a:b");
  split_kind_prefixed_name("top:H1", kind, name);  // not a kind word as written
  EXPECT_EQ(kind, SurfaceKind::Unknown);
  EXPECT_EQ(name, "top:H1");
  EXPECT_EQ(kind_prefixed_name(SurfaceKind::Boundary, "box"), "boundary:box");
}

TEST(VolumeTags, MeditSidecarOfAnotherMeshIsRefused) {
  test::ScratchDir dir;
  write_volume_mesh(tagged_cube(), dir.file("a.mesh"));
  VolumeMesh smaller = tagged_cube();
  smaller.corners.pop_back();
  smaller.corner_id.pop_back();
  write_volume_mesh(smaller, dir.file("b.mesh"));
  // a.mesh with b's sidecar: one corner fewer.
  std::filesystem::copy_file(dir.file("b.mesh.json"), dir.file("a.mesh.json"),
                             std::filesystem::copy_options::overwrite_existing);
  try {
    read_volume_mesh(dir.file("a.mesh"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.mesh.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("counts.corners"), std::string::npos) << e.what();
  }
}

TEST(VolumeTags, MalformedMeditSidecarIsAnInputErrorWithItsLine) {
  test::ScratchDir dir;
  write_volume_mesh(tagged_cube(), dir.file("a.mesh"));
  std::string text = test::read_text(dir.file("a.mesh.json"));
  const size_t at = text.find("\"regions\"");
  text.insert(at, "oops ");
  test::write_text(dir.file("a.mesh.json"), text);
  const long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + at, '\n'));
  try {
    read_volume_mesh(dir.file("a.mesh"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
  }
  // Entries of the wrong shape.
  text = test::read_text(dir.file("a.mesh.json"));
  test::write_text(dir.file("a.mesh.json"),
                   "{\"voroseal_medit_names\": 1, \"counts\": {\"vertices\": 8, \"triangles\": 12, "
                   "\"tetrahedra\": 6, \"edges\": 12, \"corners\": 8}, \"surfaces\": [{\"ref\": 0, "
                   "\"name\": \"x\"}]}");
  EXPECT_THROW(read_volume_mesh(dir.file("a.mesh")), InputError);
}

// ---- what other tools read from voroseal's files (skipped when they are not installed) ----

bool runs(const std::string& command) {
  return std::system((command + " >/dev/null 2>&1").c_str()) == 0;
}

TEST(VolumeTags, GmshReadsTheNamedGroupsAndWritesThemBack) {
  if (!runs("command -v gmsh")) GTEST_SKIP() << "gmsh is not installed";
  test::ScratchDir dir;
  const VolumeMesh m = tagged_cube();
  write_volume_mesh(m, dir.file("cube.msh"));
  const std::string q = "'" + dir.path().string() + "/";
  // Gmsh saves the elements of every physical group: points, lines, triangles, tets.
  ASSERT_TRUE(runs("gmsh " + q + "cube.msh' -save -format msh22 -o " + q + "g22.msh'"));
  ASSERT_TRUE(runs("gmsh " + q + "cube.msh' -save -format msh41 -o " + q + "g41.msh'"));
  for (const char* name : {"g22.msh", "g41.msh"}) {
    SCOPED_TRACE(name);
    const VolumeMesh read = read_volume_mesh(dir.file(name));
    expect_same_tags(read, m, false);
  }
}

TEST(VolumeTags, MeshioReadsTheNamesAndCells) {
  std::string python;
  for (const char* p : {"/usr/bin/python3", "python3"})
    if (runs(std::string(p) + " -c 'import meshio'")) {
      python = p;
      break;
    }
  if (python.empty()) GTEST_SKIP() << "python3 with meshio is not installed";
  test::ScratchDir dir;
  const VolumeMesh m = tagged_cube();
  write_volume_mesh(m, dir.file("cube.msh"));
  write_volume_mesh(m, dir.file("cube.vtu"));
  // Counts per cell type and the names meshio finds, one line per file.
  test::write_text(dir.file("read.py"),
                   "import sys, meshio\n"
                   "for f in sys.argv[2:]:\n"
                   "    m = meshio.read(sys.argv[1] + '/' + f)\n"
                   "    n = {}\n"
                   "    for b in m.cells: n[b.type] = n.get(b.type, 0) + len(b.data)\n"
                   "    print(f, sorted(n.items()), sorted(m.field_data.keys()))\n");
  const std::string out = dir.file("out.txt");
  const std::string command = python + " '" + dir.file("read.py") + "' '" + dir.path().string() +
                              "' cube.msh cube.vtu > '" + out + "'";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string text = test::read_text(out);
  const std::string counts = "[('line', 12), ('tetra', 6), ('triangle', 12), ('vertex', 8)]";
  EXPECT_NE(text.find("cube.msh " + counts), std::string::npos) << text;
  EXPECT_NE(text.find("cube.vtu " + counts), std::string::npos) << text;
  EXPECT_NE(text.find("'horizon:H1'"), std::string::npos) << text;
  EXPECT_NE(text.find("'contact:south:north+H1'"), std::string::npos) << text;
  EXPECT_NE(text.find("'region:lower'"), std::string::npos) << text;
}

}  // namespace
}  // namespace voroseal
