// `remesh --tetmesh` tet-meshes the model as written: the same mesh as `tetmesh` on the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/cli/cli_run.h"

namespace voroseal::test {
namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CliRemeshTetmesh, GivesTheMeshThatTetmeshGivesOnTheWrittenModel) {
  CliDir dir("cli_remesh_tetmesh");
  const std::string model = dir / "box.ts";
  write_box_model(model, 6);
  const CliResult remesh = run_voroseal({"-q", "remesh", model, "--seeds", "400", "-o",
                                         dir / "r.ml", "--tetmesh", dir / "direct.mesh"});
  ASSERT_EQ(remesh.exit_code, 0) << remesh.err;
  const CliResult tetmesh = run_voroseal({"-q", "tetmesh", dir / "r.ml", "-o", dir / "file.mesh"});
  ASSERT_EQ(tetmesh.exit_code, 0) << tetmesh.err;
  const std::string direct = contents(dir / "direct.mesh"), file = contents(dir / "file.mesh");
  ASSERT_NE(direct.find("Tetrahedra"), std::string::npos);
  EXPECT_TRUE(direct == file) << "remesh --tetmesh and tetmesh on the written model differ";
}

// Off a terminal (a log file, a batch job): one line per step with its time, no iteration lines.
TEST(CliRemeshTetmesh, LogOffATerminalHasOneLinePerStep) {
  CliDir dir("cli_remesh_log");
  const std::string model = dir / "box.ts";
  write_box_model(model, 6);
  const CliResult r = run_voroseal(
      {"remesh", model, "--seeds", "400", "-o", dir / "r.ml", "--tetmesh", dir / "r.mesh"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* step : {"remesh: seed sampling (", "remesh: optimising seeds (",
                           "remesh: mesh building (", "remesh: clean-up (",
                           "remesh: verdict: valid (", "tetmesh: TetGen: ", "tetmesh: writing ("})
    EXPECT_NE(r.err.find(step), std::string::npos) << step << " missing in:\n" << r.err;
  EXPECT_EQ(r.err.find("iteration  "), std::string::npos) << "per-iteration lines without -v";
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << "a terminal's redraw in a log";
  EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 30) << r.err;
}

// --quiet drops progress and info, never a warning.
TEST(CliRemeshTetmesh, QuietKeepsWarnings) {
  CliDir dir("cli_quiet_warnings");
  const std::string model = dir / "box.ts";
  write_box_model(model, 6);
  const CliResult remesh =
      run_voroseal({"-q", "remesh", model, "--seeds", "400", "-o", dir / "r.ml"});
  ASSERT_EQ(remesh.exit_code, 0) << remesh.err;
  EXPECT_EQ(remesh.err.find("remesh: optimising seeds"), std::string::npos) << remesh.err;
  const CliResult r = run_voroseal(
      // No refinement (--quality 0): TetGen is not asked for 60 deg, the census still counts.
      {"-q", "tetmesh", dir / "r.ml", "-o", dir / "r.mesh", "--quality", "0", "--min-dihedral",
       "60"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: tetmesh: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tets below 60 deg"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("tetmesh: TetGen"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace voroseal::test
