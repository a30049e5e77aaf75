// libFuzzer entry point for one reader (chosen by a VOROSEAL_FUZZ_<FORMAT> definition).
// Contract checked: a read either succeeds or throws InputError; building a model from what
// was read may throw ModelError only. Anything else (another exception, a sanitizer report, a
// crash, a timeout) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "io/gmsh_format.h"
#include "io/gocad_model3d.h"
#include "io/gocad_tsurf.h"
#include "io/medit_format.h"
#include "io/obj_format.h"
#include "io/tetgen_format.h"
#include "io/vtk_format.h"

namespace {

using namespace voroseal;

[[maybe_unused]] void build(const SurfaceSoup& soup) {
  try {
    build_model(soup);
  } catch (const ModelError&) {
  }
}

void run(const std::string& data) {
  const TextSource source{"fuzz", data};
#if defined(VOROSEAL_FUZZ_TSURF)
  build(read_tsurf(source));
#elif defined(VOROSEAL_FUZZ_MODEL3D)
  build(read_model3d(source));
#elif defined(VOROSEAL_FUZZ_OBJ)
  build(read_obj(source));
#elif defined(VOROSEAL_FUZZ_MEDIT)
  build(read_medit(source));
#elif defined(VOROSEAL_FUZZ_MEDIT_VOLUME)
  read_medit_volume(source);
#elif defined(VOROSEAL_FUZZ_VTU)
  build(read_vtu(source));
#elif defined(VOROSEAL_FUZZ_VTU_VOLUME)
  read_vtu_volume(source);
#elif defined(VOROSEAL_FUZZ_GMSH)
  build(read_msh(source));
#elif defined(VOROSEAL_FUZZ_GMSH_VOLUME)
  read_msh_volume(source);
#elif defined(VOROSEAL_FUZZ_TETGEN)
  // The three files separated by form feeds: node \f ele \f face.
  const size_t a = data.find('\f');
  const size_t b = a == std::string::npos ? a : data.find('\f', a + 1);
  if (b == std::string::npos) return;
  const TextSource node{"fuzz.node", data.substr(0, a)}, ele{"fuzz.ele", data.substr(a + 1, b - a - 1)},
      face{"fuzz.face", data.substr(b + 1)};
  read_tetgen(node, ele, &face);
#else
#error "define VOROSEAL_FUZZ_<FORMAT>"
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    run(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const voroseal::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
