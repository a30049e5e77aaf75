// Tags of tetrahedralize() meshes: one surface id per input surface (all its pieces), named and
// of its kind, the model's contact segments as edges and its corners as points, through files.
#include "modules/tetmesh/surface_tags.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <unistd.h>

#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "modules/tetmesh/tetrahedralize.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

Logger quiet() {
  return Logger(LogLevel::Quiet);
}

std::set<std::pair<int, int>> triangle_edges(const VolumeMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  return edges;
}

// Length of the edges of each contact id.
std::map<int, double> contact_lengths(const VolumeMesh& mesh) {
  std::map<int, double> length;
  for (size_t e = 0; e < mesh.edges.size(); ++e)
    length[mesh.edge_contact[e]] +=
        (mesh.vertices[mesh.edges[e][0]] - mesh.vertices[mesh.edges[e][1]]).norm();
  return length;
}

class FaultedLayers : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new StructuralModel(read_model(test::bundled_model("faulted_layers.ts")));
    TetmeshOptions options;
    options.sliver_passes = 0;
    options.refine_surface_below_deg = 0.0;
    Logger log = quiet();
    mesh_ = new VolumeMesh(tetrahedralize(*model_, options, log));
  }
  static void TearDownTestSuite() {
    delete mesh_;
    delete model_;
  }
  static StructuralModel* model_;
  static VolumeMesh* mesh_;
};
StructuralModel* FaultedLayers::model_ = nullptr;
VolumeMesh* FaultedLayers::mesh_ = nullptr;

TEST_F(FaultedLayers, OneSurfaceIdPerInputSurfaceNamedWithItsKind) {
  const StructuralModel& model = *model_;
  const VolumeMesh& mesh = *mesh_;
  // The fault cuts the horizons into pieces: more parts than surfaces.
  ASSERT_EQ(model.interfaces.size(), 9u);
  ASSERT_GT(model.parts.size(), model.interfaces.size());
  ASSERT_EQ(mesh.surface_names.size(), model.interfaces.size());
  std::map<std::string, SurfaceKind> kind;
  for (size_t s = 0; s < mesh.surface_names.size(); ++s)
    kind[mesh.surface_names[s]] = mesh.surface_kind(static_cast<int>(s));
  EXPECT_EQ(kind.at("H1"), SurfaceKind::Horizon);
  EXPECT_EQ(kind.at("F1"), SurfaceKind::Fault);
  EXPECT_EQ(kind.at("boundary_top"), SurfaceKind::Boundary);
  // Every triangle of every piece of a surface carries the surface's id; every surface is used.
  ASSERT_EQ(mesh.triangle_part.size(), mesh.triangles.size());
  std::map<int, std::set<int>> parts_of_surface;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int part = mesh.triangle_part[t];
    EXPECT_EQ(mesh.triangle_surface[t], model.parts[part].interface);
    EXPECT_EQ(mesh.part_names[part], model.parts[part].name);
    parts_of_surface[mesh.triangle_surface[t]].insert(part);
  }
  EXPECT_EQ(parts_of_surface.size(), model.interfaces.size());
  for (size_t i = 0; i < model.interfaces.size(); ++i)
    EXPECT_EQ(parts_of_surface[static_cast<int>(i)],
              std::set<int>(model.interfaces[i].parts.begin(), model.interfaces[i].parts.end()))
        << model.interfaces[i].name;
}

TEST_F(FaultedLayers, ContactsAreEdgesAndCornersPointsOfTheMesh) {
  const StructuralModel& model = *model_;
  const VolumeMesh& mesh = *mesh_;
  size_t segments = 0;
  for (const Contact& c : model.contacts) segments += c.vertices.size() - 1;
  ASSERT_GT(segments, 0u);
  EXPECT_EQ(mesh.edges.size(), segments);
  EXPECT_EQ(mesh.corners.size(), model.corners.size());
  const std::set<std::pair<int, int>> edges = triangle_edges(mesh);
  for (const Edge& e : mesh.edges) EXPECT_TRUE(edges.count(std::minmax(e[0], e[1])));
  // Each segment joins the mesh vertices at the model vertices' places.
  size_t e = 0;
  for (const Contact& c : model.contacts)
    for (size_t k = 0; k + 1 < c.vertices.size(); ++k, ++e) {
      EXPECT_EQ(mesh.vertices[mesh.edges[e][0]], model.vertices[c.vertices[k]]);
      EXPECT_EQ(mesh.vertices[mesh.edges[e][1]], model.vertices[c.vertices[k + 1]]);
    }
  for (size_t k = 0; k < model.corners.size(); ++k)
    EXPECT_EQ(mesh.vertices[mesh.corners[k]], model.vertices[model.corners[k].vertex]);
  // Contacts named by the surfaces meeting there: the fault trace on H1 among them.
  const auto& names = mesh.contact_names;
  EXPECT_NE(std::find(names.begin(), names.end(), "H1+F1"), names.end());
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  EXPECT_LT(names.size(), model.contacts.size());  // grouped by surfaces, not per line
}

TEST_F(FaultedLayers, MshCarriesOneNamedGroupPerSurfaceAndReadsBack) {
  const VolumeMesh& mesh = *mesh_;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("voroseal_surface_tags_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* ext : {".msh", ".vtu", ".mesh"}) {
    SCOPED_TRACE(ext);
    const std::string path = (dir / (std::string("faulted") + ext)).string();
    write_volume_mesh(mesh, path);
    const VolumeMesh back = read_volume_mesh(path);
    EXPECT_EQ(back.surface_names, mesh.surface_names);
    EXPECT_EQ(back.surface_kinds, mesh.surface_kinds);
    EXPECT_EQ(back.triangle_surface.size(), mesh.triangle_surface.size());
    EXPECT_EQ(back.contact_names, mesh.contact_names);
    EXPECT_EQ(back.corner_names, mesh.corner_names);
    EXPECT_EQ(back.edges.size(), mesh.edges.size());
    EXPECT_EQ(back.corners.size(), mesh.corners.size());
    EXPECT_EQ(contact_lengths(back), contact_lengths(mesh));
  }
  std::filesystem::remove_all(dir);
}

TEST(SurfaceTags, ContactSegmentsTetGenSplitBecomeTheEdgesAlongThem) {
  // Without Y and with a volume bound TetGen splits surface triangles and contact segments.
  const StructuralModel model = build_model(test::lattice_box(2, true));
  TetmeshOptions options;
  options.keep_surface = false;
  options.max_volume = 0.001;
  Logger log = quiet();
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  ASSERT_GT(run.split_facets, 0);
  size_t segments = 0;
  std::map<int, double> model_lengths;
  std::map<std::set<int>, int> id_of_surfaces;
  for (const Contact& c : model.contacts) {
    segments += c.vertices.size() - 1;
    std::set<int> surfaces;
    for (int p : c.parts) surfaces.insert(model.parts[p].interface);
    const int id = id_of_surfaces.emplace(surfaces, int(id_of_surfaces.size())).first->second;
    for (size_t k = 0; k + 1 < c.vertices.size(); ++k)
      model_lengths[id] +=
          (model.vertices[c.vertices[k]] - model.vertices[c.vertices[k + 1]]).norm();
  }
  EXPECT_GT(mesh.edges.size(), segments);  // split
  const std::set<std::pair<int, int>> edges = triangle_edges(mesh);
  for (const Edge& e : mesh.edges) EXPECT_TRUE(edges.count(std::minmax(e[0], e[1])));
  const std::map<int, double> lengths = contact_lengths(mesh);
  ASSERT_EQ(lengths.size(), model_lengths.size());
  for (const auto& [id, length] : model_lengths) EXPECT_NEAR(lengths.at(id), length, 1e-9) << id;
}

}  // namespace
}  // namespace voroseal
