// Writes valid seed files for the fuzzers: <dir>/<format>/seed_*.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/model/model_builder.h"
#include "io/gmsh_format.h"
#include "io/gocad_model3d.h"
#include "io/gocad_tsurf.h"
#include "io/medit_format.h"
#include "io/obj_format.h"
#include "io/tetgen_format.h"
#include "io/vtk_format.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

using namespace voroseal;

namespace {

void put(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
}

template <class Write, class Object>
std::string text(Write write, const Object& object) {
  std::ostringstream out;
  write(object, out, 17);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path root = argc > 1 ? argv[1] : "corpus";
  const StructuralModel model = build_model(test::lattice_box(2, true));
  const VolumeMesh mesh = test::cube_tet_mesh();
  put(root / "ts", "seed_model.ts", text(write_tsurf, model));
  put(root / "ml", "seed_model.ml", text(write_model3d, model));
  put(root / "obj", "seed_model.obj", text(write_obj, model));
  put(root / "mesh", "seed_model.mesh", text(write_medit, model));
  put(root / "mesh", "seed_volume.mesh", text(write_medit_volume, mesh));
  put(root / "vtu", "seed_model.vtu", text(write_vtu, model));
  put(root / "vtu", "seed_volume.vtu", text(write_vtu_volume, mesh));
  put(root / "msh", "seed_model.msh", text(write_msh, model));
  put(root / "msh", "seed_volume.msh", text(write_msh_volume, mesh));
  std::ostringstream tetgen;
  write_tetgen_node(mesh, tetgen, 17);
  tetgen << '\f';
  write_tetgen_ele(mesh, tetgen);
  tetgen << '\f';
  write_tetgen_face(mesh, tetgen);
  put(root / "tetgen", "seed_cube", tetgen.str());
  return 0;
}
