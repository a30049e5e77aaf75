// Every model and volume format written then read back gives the same model / mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <tuple>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "io/vtk_format.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using Point = std::array<double, 3>;
Point key(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

std::vector<Point> file_points(const StructuralModel& m) {
  std::vector<Point> p;
  for (const Vec3& v : m.vertices) p.push_back(key(v + m.frame.origin));
  std::sort(p.begin(), p.end());
  return p;
}

// Oriented triangles as file coordinates, rotated to start at their smallest corner.
std::vector<std::array<Point, 3>> oriented_triangles(const StructuralModel& m) {
  std::vector<std::array<Point, 3>> out;
  for (const Triangle& t : flatten(m).triangles) {
    std::array<Point, 3> c{key(m.vertices[t[0]] + m.frame.origin), key(m.vertices[t[1]] + m.frame.origin),
                           key(m.vertices[t[2]] + m.frame.origin)};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<double> region_volumes(const StructuralModel& m) {
  std::vector<double> v;
  for (const Region& r : m.regions) v.push_back(-m.signed_volume(r.sides));
  return v;
}

std::set<std::pair<std::string, SurfaceKind>> interface_kinds(const StructuralModel& m) {
  std::set<std::pair<std::string, SurfaceKind>> s;
  for (const Interface& i : m.interfaces) s.insert({i.name, i.kind});
  return s;
}

struct ModelCase {
  std::string name;
  SurfaceSoup soup;
};

std::vector<ModelCase> model_cases() {
  const Vec3 lo(512345.25, 4012345.5, -3500.0), hi(522345.25, 4020345.5, -500.0);
  SurfaceSoup fault_box = test::lattice_box(4, false);
  test::append(fault_box, test::floating_fault(3, 0.5, 0.25, 0.75));
  return {{"box", test::lattice_box(4, false)},
          {"box_with_horizon", test::lattice_box(4, true)},
          {"utm_box_with_horizon", test::lattice_box(2, true, lo, hi)},
          {"shuffled_orientation", test::lattice_box(4, true, Vec3(0, 0, 0), Vec3(1, 1, 1), 7)},
          {"floating_fault", fault_box}};
}

class ModelRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(ModelRoundTrip, KeepsTopologyVolumesAndExactCoordinates) {
  const std::string ext = GetParam();
  test::ScratchDir dir;
  for (const ModelCase& c : model_cases()) {
    SCOPED_TRACE(c.name + ext);
    const StructuralModel m1 = build_model(c.soup);
    const std::string path = dir.file(c.name + ext);
    write_model(m1, path);
    const StructuralModel m2 = read_model(path);
    EXPECT_EQ(m2.vertices.size(), m1.vertices.size());
    EXPECT_EQ(m2.num_triangles(), m1.num_triangles());
    EXPECT_EQ(m2.parts.size(), m1.parts.size());
    EXPECT_EQ(m2.contacts.size(), m1.contacts.size());
    EXPECT_EQ(m2.corners.size(), m1.corners.size());
    ASSERT_EQ(m2.regions.size(), m1.regions.size());
    EXPECT_EQ(m2.frame.origin, m1.frame.origin);
    // Coordinates are bit-identical and every triangle keeps its orientation.
    EXPECT_EQ(file_points(m2), file_points(m1));
    EXPECT_EQ(oriented_triangles(m2), oriented_triangles(m1));
    std::vector<double> v1 = region_volumes(m1), v2 = region_volumes(m2);
    std::sort(v1.begin(), v1.end());
    std::sort(v2.begin(), v2.end());
    for (size_t r = 0; r < v1.size(); ++r) EXPECT_NEAR(v2[r], v1[r], 1e-12 * std::abs(v1[r]));
    EXPECT_NEAR(m2.signed_volume(m2.universe.sides), m1.signed_volume(m1.universe.sides),
                1e-12 * std::abs(m1.signed_volume(m1.universe.sides)));
    // Formats that carry interface names and kinds keep them.
    if (ext == ".obj" || ext == ".ts" || ext == ".ml" || ext == ".msh") {
      EXPECT_EQ(interface_kinds(m2), interface_kinds(m1));
    }
    if (ext == ".msh" || ext == ".obj") {
      std::set<std::string> n1, n2;
      for (const SurfacePart& p : m1.parts) n1.insert(p.name);
      for (const SurfacePart& p : m2.parts) n2.insert(p.name);
      EXPECT_EQ(n2, n1);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFormats, ModelRoundTrip, ::testing::ValuesIn(writable_model_extensions()),
                         [](const auto& info) { return info.param.substr(1); });

TEST(Model3dRoundTrip, KeepsRegionNamesLayersAndExplicitSides) {
  StructuralModel m1 = build_model(test::lattice_box(4, true, Vec3(-10, -10, -10), Vec3(30, 50, 10)));
  ASSERT_EQ(m1.regions.size(), 2u);
  m1.regions[0].name = "Lower block";  // a blank: written as one token
  m1.regions[1].name = "upper";
  m1.layers = {{"first", {0}}, {"both", {1, 0}}};
  test::ScratchDir dir;
  const std::string path = dir.file("model.ml");
  write_model(m1, path);
  const StructuralModel m2 = read_model(path);
  EXPECT_TRUE(m2.build.explicit_regions);
  ASSERT_EQ(m2.regions.size(), 2u);
  EXPECT_EQ(m2.regions[0].name, "Lower_block");
  EXPECT_EQ(m2.regions[1].name, "upper");
  ASSERT_EQ(m2.layers.size(), 2u);
  EXPECT_EQ(m2.layers[0].name, "first");
  EXPECT_EQ(m2.layers[0].regions, std::vector<int>{0});
  EXPECT_EQ(m2.layers[1].name, "both");
  EXPECT_EQ(m2.layers[1].regions, (std::vector<int>{1, 0}));
  for (size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(m2.regions[r].sides.size(), m1.regions[r].sides.size());
    EXPECT_NEAR(m2.signed_volume(m2.regions[r].sides), m1.signed_volume(m1.regions[r].sides), 1e-9);
  }
  // The explicit regions agree with the ones inferred from the surfaces.
  ReadOptions infer;
  infer.build.ignore_explicit_regions = true;
  const StructuralModel m3 = read_model(path, infer);
  ASSERT_EQ(m3.regions.size(), 2u);
  std::set<std::vector<Side>> explicit_sides, inferred_sides;
  for (const Region& r : m2.regions) {
    std::vector<Side> s = r.sides;
    std::sort(s.begin(), s.end());
    explicit_sides.insert(s);
  }
  for (const Region& r : m3.regions) inferred_sides.insert(r.sides);
  EXPECT_EQ(explicit_sides, inferred_sides);
}

// Tet mesh round trip: same vertices (file coordinates, bit-identical), same tets with the same
// regions, same triangles with the same surfaces. Gmsh groups elements by entity, so compare
// the element sets.
using TetKey = std::tuple<std::array<Point, 4>, int>;
using TriKey = std::tuple<std::array<Point, 3>, int>;

std::vector<TetKey> tets_of(const VolumeMesh& m) {
  std::vector<TetKey> out;
  for (size_t k = 0; k < m.tets.size(); ++k) {
    std::array<Point, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = key(m.vertices[m.tets[k][i]] + m.frame.origin);
    out.emplace_back(p, m.tet_region[k]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<TriKey> triangles_of(const VolumeMesh& m) {
  std::vector<TriKey> out;
  for (size_t k = 0; k < m.triangles.size(); ++k) {
    std::array<Point, 3> p;
    for (int i = 0; i < 3; ++i) p[i] = key(m.vertices[m.triangles[k][i]] + m.frame.origin);
    out.emplace_back(p, m.triangle_surface[k]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

class VolumeRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(VolumeRoundTrip, KeepsTetsRegionsAndSurfaces) {
  const std::string ext = GetParam();
  test::ScratchDir dir;
  const VolumeMesh m1 = test::cube_tet_mesh();
  const std::string path = dir.file("cube" + ext);
  write_volume_mesh(m1, path);
  const VolumeMesh m2 = read_volume_mesh(path);
  ASSERT_EQ(m2.vertices.size(), m1.vertices.size());
  ASSERT_EQ(m2.tets.size(), m1.tets.size());
  ASSERT_EQ(m2.triangles.size(), m1.triangles.size());
  for (size_t v = 0; v < m1.vertices.size(); ++v)
    EXPECT_EQ(key(m2.vertices[v] + m2.frame.origin), key(m1.vertices[v] + m1.frame.origin));
  EXPECT_EQ(tets_of(m2), tets_of(m1));
  EXPECT_EQ(triangles_of(m2), triangles_of(m1));
  EXPECT_GE(m2.region_names.size(), 2u);
  EXPECT_GE(m2.surface_names.size(), 6u);
  if (ext == ".msh") {
    EXPECT_EQ(m2.region_names, m1.region_names);
    EXPECT_EQ(m2.surface_names, m1.surface_names);
  }
  // Every tet keeps a positive orientation.
  for (const Tetrahedron& t : m2.tets) {
    const Vec3& a = m2.vertices[t[0]];
    EXPECT_GT((m2.vertices[t[1]] - a).dot((m2.vertices[t[2]] - a).cross(m2.vertices[t[3]] - a)), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllFormats, VolumeRoundTrip, ::testing::Values(".mesh", ".vtu", ".msh", ".node"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(VolumeRoundTrip, TetgenWritesThreeFilesAndReadsFromAnyOfThem) {
  test::ScratchDir dir;
  write_volume_mesh(test::cube_tet_mesh(), dir.file("cube.ele"));
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"cube.ele", "cube.face", "cube.node"}));
  for (const char* name : {"cube.node", "cube.ele", "cube.face"}) {
    const VolumeMesh m = read_volume_mesh(dir.file(name));
    EXPECT_EQ(m.tets.size(), 6u);
    EXPECT_EQ(m.triangles.size(), 12u);
  }
}

TEST(VolumeRoundTrip, VtuCarriesQuality) {
  // The quality of the cube's boundary triangles (right isoceles) is 6S/(sqrt3 h p). The ASCII
  // writer shows it; vtu_encoding_test decodes it from the compressed one.
  std::ostringstream out;
  write_vtu_volume_ascii(test::cube_tet_mesh(), out, 17);
  const std::string text = out.str();
  const double s = 2.0, h = 2.0 * std::sqrt(2.0), p = 0.5 * (4.0 + h);
  const double q = 6.0 * s / (std::sqrt(3.0) * h * p);
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.9g", q);
  EXPECT_NE(text.find(expected), std::string::npos) << expected;
  EXPECT_NE(text.find("Name=\"quality\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"region\""), std::string::npos);
}

TEST(ModelIo, ExtensionsAreCaseInsensitive) {
  test::ScratchDir dir;
  const StructuralModel m = build_model(test::lattice_box(2, false));
  write_model(m, dir.file("BOX.OBJ"));
  EXPECT_EQ(read_model(dir.file("BOX.OBJ")).parts.size(), 6u);
}

TEST(ModelIo, UnknownExtensionsListTheSupportedOnes) {
  test::ScratchDir dir;
  test::write_text(dir.file("model.stl"), "solid x\n");
  try {
    read_soup(dir.file("model.stl"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find(".ml"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find(".obj"), std::string::npos) << e.what();
  }
  const StructuralModel m = build_model(test::lattice_box(2, false));
  EXPECT_THROW(write_model(m, dir.file("model.stl")), OutputError);
  EXPECT_THROW(write_volume_mesh(test::cube_tet_mesh(), dir.file("mesh.obj")), OutputError);
  EXPECT_THROW(read_volume_mesh(dir.file("model.stl")), InputError);
  EXPECT_THROW(read_soup(dir.file("missing.obj")), InputError);
}

}  // namespace
}  // namespace voroseal
