// `remesh --tetmesh` tet-meshes the model as written: the same mesh as `tetmesh` on the file.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace voroseal::test
