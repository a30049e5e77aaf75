// The outputs of one command are checked before any computation; inputs that are not model
// files are named; nothing invalid is written under the output name.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/geometry/volume_quality.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "tests/cli/cli_run.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

namespace voroseal::test {
namespace {

class CliOutputs : public ::testing::Test {
 protected:
  void SetUp() override { write_box_model(model_); }
  CliDir dir_{"cli_outputs"};
  std::string model_ = dir_ / "box.ts";
};

TEST_F(CliOutputs, OutputsThatCollideOrCannotBeWrittenAreRefusedUpFront) {
  const std::string x = dir_ / "x.mesh";
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  // 200,000 seeds would take minutes: a refusal that comes back at all came before the work.
  const std::vector<Case> cases = {
      {{"remesh", model_, "--seeds", "200000", "--tetmesh", x, "-o", x},
       "also the file of --output"},
      {{"remesh", model_, "--seeds", "200000", "--dump-seeds", x, "-o", x},
       "also the file of --dump-seeds"},
      {{"remesh", model_, "--seeds", "200000", "-o", dir_ / "out.xyz"}, "unknown extension '.xyz'"},
      {{"remesh", model_, "--seeds", "200000", "-o", model_}, "is an input of this run"},
      {{"remesh", model_, "--seeds", "200000", "-o", dir_ / "missing/out.obj"}, "no directory"},
      {{"remesh", model_, "--seeds", "200000", "-o", dir_.path().string()}, "is a directory"},
      {{"remesh", model_, "--seeds", "200000", "-o", dir_ / "a.obj", "--keep-invalid",
        dir_ / "a.obj"},
       "also the file of"},
      {{"tetmesh", model_, "-o", dir_ / "out.obj"}, "unknown extension '.obj'"},
      {{"convert", model_, dir_ / "out.txt"}, "unknown extension '.txt'"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_voroseal(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.says << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(dir_.entries(), std::vector<std::string>{"box.ts"}) << c.says;
  }
}

TEST_F(CliOutputs, ConvertTakesItsOutputAsListedByModules) {
  EXPECT_EQ(run_voroseal({"convert", model_, dir_ / "a.obj"}).exit_code, 0);
  EXPECT_EQ(run_voroseal({"convert", model_, "--output", dir_ / "b.ml"}).exit_code, 0);
  EXPECT_EQ(run_voroseal({"convert", model_, "-o", dir_ / "c.msh"}).exit_code, 0);
  EXPECT_EQ(dir_.entries(), (std::vector<std::string>{"a.obj", "b.ml", "box.ts", "c.msh"}));
  EXPECT_NE(run_voroseal({"modules"}).out.find("output (or --output)"), std::string::npos);
}

TEST_F(CliOutputs, ADirectoryGivenAsTheModelIsNamed) {
  const CliResult r = run_voroseal({"check", dir_.path().string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(dir_.path().string() + ":0: is a directory"), std::string::npos) << r.err;
}

TEST_F(CliOutputs, CheckFindsTheBrokenTetsOfAVolumeMesh) {
  VolumeMesh mesh = cube_tet_mesh();
  const std::string good = dir_ / "good.mesh";
  write_volume_mesh(mesh, good);
  EXPECT_EQ(run_voroseal({"check", good}).exit_code, 0);
  // One tet names a vertex twice; another is turned inside out.
  mesh.tets[0][3] = mesh.tets[0][2];
  std::swap(mesh.tets[1][0], mesh.tets[1][1]);
  const std::string bad = dir_ / "bad.mesh";
  write_volume_mesh(mesh, bad);
  const CliResult r = run_voroseal({"check", bad, "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  auto count = [&](const std::string& name) {
    for (const nlohmann::json& c : report.at("checks"))
      if (c.at("name") == name) return c.at("count").get<long>();
    return -1L;
  };
  EXPECT_EQ(count("repeated_vertex_tets"), 1);
  EXPECT_EQ(count("inverted_tets"), 1);
  EXPECT_EQ(count("flat_tets"), 0);
  // The inverted tet lies on the same side of a face as its neighbour: they overlap.
  EXPECT_GE(count("nonconformal_faces"), 1);
  // stats says what the tet is: no tet at all, not a flat one.
  const VolumeQuality q = measure_volume(mesh);
  EXPECT_EQ(q.repeated_vertex_tets, 1);
  EXPECT_EQ(q.nonpositive_tets, 1);
}

TEST_F(CliOutputs, CheckFindsTetsThatOverlapOrShareAFaceWithTwoOthers) {
  VolumeMesh mesh = cube_tet_mesh();
  mesh.tets.push_back(mesh.tets[0]);  // a duplicate: each of its faces now has a third tet
  mesh.tet_region.push_back(0);
  const std::string path = dir_ / "twice.mesh";
  write_volume_mesh(mesh, path);
  const CliResult r = run_voroseal({"check", path});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("nonconformal_faces"), std::string::npos) << r.out;
}

TEST_F(CliOutputs, AnInvalidRemeshIsNotWrittenUnderTheOutputName) {
  // The box with a fault floating through the horizon, remeshed without the clean-up: the raw
  // dual crosses where the input does and has degenerate triangles where cells meet there.
  const std::string input = dir_ / "faulted.obj";
  {
    SurfaceSoup soup = lattice_box(6, true);
    append(soup, floating_fault(6, 0.5, 0.3, 0.7));
    write_model(build_model(soup), input);
  }
  const std::string out = dir_ / "out.obj", kept = dir_ / "kept.obj", tets = dir_ / "out.mesh";
  const CliResult r = run_voroseal(
      {"remesh", input, "--seeds", "400", "--iterations", "20", "--no-cleanup", "-o", out,
       "--tetmesh", tets});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("self_intersections"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" at "), std::string::npos) << r.err;  // the places named
  EXPECT_NE(r.err.find("nothing written to " + out), std::string::npos) << r.err;
  EXPECT_EQ(dir_.entries(), (std::vector<std::string>{"box.ts", "faulted.obj"}));
  const CliResult keep = run_voroseal(
      {"remesh", input, "--seeds", "400", "--iterations", "20", "--no-cleanup", "-o", out,
       "--keep-invalid", kept});
  EXPECT_EQ(keep.exit_code, 1);
  EXPECT_EQ(dir_.entries(), (std::vector<std::string>{"box.ts", "faulted.obj", "kept.obj"}));
  // What was kept is what `check` calls invalid.
  EXPECT_EQ(run_voroseal({"check", kept}).exit_code, 1);
}

}  // namespace
}  // namespace voroseal::test
