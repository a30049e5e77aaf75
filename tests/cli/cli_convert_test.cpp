// `voroseal convert` on volume meshes: every format it writes tets to keeps the tets, their
// region ids and the surface triangles (and, but for TetGen files, which are then refused, the
// contact edges, corner points and names); a format that holds surfaces only is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "modules/tetmesh/tetrahedralize.h"
#include "tests/cli/cli_run.h"
#include "tests/support/test_models.h"

namespace voroseal::test {
namespace {

std::map<int, long> tets_per_region(const VolumeMesh& mesh) {
  std::map<int, long> count;
  for (int r : mesh.tet_region) ++count[r];
  return count;
}

std::map<int, long> triangles_per_surface(const VolumeMesh& mesh) {
  std::map<int, long> count;
  for (int s : mesh.triangle_surface) ++count[s];
  return count;
}

class CliConvert : public ::testing::Test {
 protected:
  void SetUp() override {
    Logger log(LogLevel::Quiet);
    mesh_ = tetrahedralize(build_model(lattice_box(3, true)), TetmeshOptions{}, log);
    write_volume_mesh(mesh_, source_);
  }
  CliDir dir_{"cli_convert"};
  std::string source_ = dir_ / "vol.mesh";
  VolumeMesh mesh_;
};

TEST_F(CliConvert, KeepsTetsRegionsSurfacesContactsAndCornersThroughEveryVolumeFormat) {
  ASSERT_GT(mesh_.tets.size(), 0u);
  ASSERT_GT(tets_per_region(mesh_).size(), 1u);
  ASSERT_GT(mesh_.edges.size(), 0u);
  ASSERT_GT(mesh_.corners.size(), 0u);
  // Each hop reads the previous file: .mesh -> .vtu -> .msh -> .mesh.
  const std::vector<std::string> chain = {source_, dir_ / "a.vtu", dir_ / "b.msh", dir_ / "d.mesh"};
  for (size_t i = 1; i < chain.size(); ++i) {
    const CliResult r = run_voroseal({"convert", chain[i - 1], chain[i]});
    ASSERT_EQ(r.exit_code, 0) << chain[i - 1] << " -> " << chain[i] << ": " << r.err;
    const VolumeMesh back = read_volume_mesh(chain[i]);
    EXPECT_EQ(back.tets.size(), mesh_.tets.size()) << chain[i];
    EXPECT_EQ(back.vertices.size(), mesh_.vertices.size()) << chain[i];
    EXPECT_EQ(tets_per_region(back), tets_per_region(mesh_)) << chain[i];
    EXPECT_EQ(triangles_per_surface(back), triangles_per_surface(mesh_)) << chain[i];
    EXPECT_EQ(back.surface_names, mesh_.surface_names) << chain[i];
    EXPECT_EQ(back.surface_kinds, mesh_.surface_kinds) << chain[i];
    EXPECT_EQ(back.region_names, mesh_.region_names) << chain[i];
    EXPECT_EQ(back.contact_names, mesh_.contact_names) << chain[i];
    EXPECT_EQ(back.corner_names, mesh_.corner_names) << chain[i];
    EXPECT_EQ(back.edges.size(), mesh_.edges.size()) << chain[i];
    EXPECT_EQ(back.corners.size(), mesh_.corners.size()) << chain[i];
  }
}

// --ascii writes a .vtu whose arrays are all text, which reads back to the same mesh; without
// it the arrays are compressed binary.
TEST_F(CliConvert, AsciiVtuHoldsTextArraysAndReadsBackTheSame) {
  const std::string text = dir_ / "ascii.vtu", binary = dir_ / "binary.vtu";
  ASSERT_EQ(run_voroseal({"convert", source_, text, "--ascii"}).exit_code, 0);
  ASSERT_EQ(run_voroseal({"convert", source_, binary}).exit_code, 0);
  const auto arrays = [](const std::string& path, const std::string& format) {
    std::ifstream in(path);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    long n = 0;
    for (size_t at = all.find("format=\"" + format + "\""); at != std::string::npos;
         at = all.find("format=\"" + format + "\"", at + 1))
      ++n;
    return n;
  };
  EXPECT_GT(arrays(text, "ascii"), 0);
  EXPECT_EQ(arrays(text, "binary") + arrays(text, "appended"), 0);
  EXPECT_EQ(arrays(binary, "ascii"), 0);
  const VolumeMesh back = read_volume_mesh(text);
  EXPECT_EQ(back.tets, read_volume_mesh(binary).tets);
  EXPECT_EQ(tets_per_region(back), tets_per_region(mesh_));
  EXPECT_EQ(back.region_names, mesh_.region_names);
}

TEST_F(CliConvert, TetGenFilesKeepTetsButRefuseContactsAndCorners) {
  const CliResult refused = run_voroseal({"convert", source_, dir_ / "c.node"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("TetGen files hold neither"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "c.node"));
  // Without edges and corners the tets, regions and surfaces go through.
  VolumeMesh bare = mesh_;
  bare.edges.clear();
  bare.edge_contact.clear();
  bare.corners.clear();
  bare.corner_id.clear();
  write_volume_mesh(bare, dir_ / "bare.msh");
  const CliResult r = run_voroseal({"convert", dir_ / "bare.msh", dir_ / "c.node"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const VolumeMesh back = read_volume_mesh(dir_ / "c.node");
  EXPECT_EQ(back.tets.size(), mesh_.tets.size());
  EXPECT_EQ(tets_per_region(back), tets_per_region(mesh_));
  EXPECT_EQ(triangles_per_surface(back), triangles_per_surface(mesh_));
}

TEST_F(CliConvert, RefusesAFormatThatCannotHoldTets) {
  for (const char* target : {"x.ts", "x.obj", "x.ml"}) {
    const CliResult r = run_voroseal({"convert", source_, dir_ / target});
    EXPECT_EQ(r.exit_code, 2) << target;
    EXPECT_NE(r.err.find("the tets would be lost"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / target)) << target;
  }
}

TEST_F(CliConvert, RefusesToWriteSurfacesAsTetGenFiles) {
  const std::string model = dir_ / "box.ts";
  write_box_model(model);
  const CliResult r = run_voroseal({"convert", model, dir_ / "x.node"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds surfaces only"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace voroseal::test
