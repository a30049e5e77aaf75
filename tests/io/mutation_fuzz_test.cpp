// Deterministic mutation fuzzing: small valid files of every format, mutated thousands of times
// (byte flips, hostile tokens, deleted / duplicated / swapped lines, truncation). Every read
// must either succeed or throw InputError; building a model from what was read may only throw
// ModelError. A crash, a hang or another exception fails the test.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <sstream>

#include "framework/core/error.h"
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

namespace voroseal {
namespace {

const char* const kHostileTokens[] = {"nan", "NaN", "inf", "-inf", "1e308", "1e309", "-1e308", "4.9e-324", "-1",
                                      "0", "-0", "2147483648", "-2147483649", "9223372036854775807",
                                      "99999999999999999999", "1.5", "+", "-", "x", "", "\"", "{", "}", "<", ">",
                                      "/", "//", "$", "END", "TFACE", "GOCAD", "End", "Vertices", "$EndNodes",
                                      "</DataArray>", "1/2/3"};

class Mutator {
 public:
  explicit Mutator(unsigned seed) : rng_(seed) {}

  std::string mutate(std::string text) {
    const int rounds = 1 + static_cast<int>(rng_() % 3);
    for (int r = 0; r < rounds; ++r) {
      switch (rng_() % 8) {
        case 0: flip_byte(text); break;
        case 1:
        case 2: replace_token(text); break;
        case 3: delete_line(text); break;
        case 4: duplicate_line(text); break;
        case 5: swap_lines(text); break;
        case 6: truncate(text); break;
        default: insert_token(text); break;
      }
    }
    return text;
  }

 private:
  size_t pick(size_t n) { return n == 0 ? 0 : rng_() % n; }

  void flip_byte(std::string& t) {
    if (t.empty()) return;
    const size_t i = pick(t.size());
    t[i] = (rng_() & 1) ? static_cast<char>(t[i] ^ (1 << (rng_() % 8))) : static_cast<char>(rng_() % 256);
  }

  // Token boundaries: runs of non-blank characters.
  std::vector<std::pair<size_t, size_t>> tokens(const std::string& t) {
    std::vector<std::pair<size_t, size_t>> out;
    size_t i = 0;
    while (i < t.size()) {
      while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
      const size_t s = i;
      while (i < t.size() && !std::isspace(static_cast<unsigned char>(t[i]))) ++i;
      if (i > s) out.emplace_back(s, i - s);
    }
    return out;
  }

  void replace_token(std::string& t) {
    const auto tok = tokens(t);
    if (tok.empty()) return;
    const auto [s, n] = tok[pick(tok.size())];
    const char* with = kHostileTokens[pick(std::size(kHostileTokens))];
    t.replace(s, n, with);
  }

  void insert_token(std::string& t) {
    const size_t at = pick(t.size() + 1);
    t.insert(at, std::string(" ") + kHostileTokens[pick(std::size(kHostileTokens))] + " ");
  }

  std::vector<std::string> lines(const std::string& t) {
    std::vector<std::string> l;
    std::istringstream in(t);
    for (std::string s; std::getline(in, s);) l.push_back(s);
    return l;
  }
  static std::string join(const std::vector<std::string>& l) {
    std::string s;
    for (const auto& x : l) s += x + "\n";
    return s;
  }

  void delete_line(std::string& t) {
    auto l = lines(t);
    if (l.empty()) return;
    l.erase(l.begin() + pick(l.size()));
    t = join(l);
  }
  void duplicate_line(std::string& t) {
    auto l = lines(t);
    if (l.empty()) return;
    const size_t i = pick(l.size());
    l.insert(l.begin() + pick(l.size() + 1), l[i]);
    t = join(l);
  }
  void swap_lines(std::string& t) {
    auto l = lines(t);
    if (l.size() < 2) return;
    std::swap(l[pick(l.size())], l[pick(l.size())]);
    t = join(l);
  }
  void truncate(std::string& t) { t.resize(pick(t.size() + 1)); }

  std::mt19937 rng_;
};

// A reader under test: takes the (mutated) texts, throws what it throws.
using Reader = std::function<void(const std::vector<TextSource>&)>;

void model_read(const std::function<SurfaceSoup(const TextSource&)>& read, const TextSource& source) {
  const SurfaceSoup soup = read(source);
  try {
    build_model(soup);
  } catch (const ModelError&) {
    // The surfaces were readable but do not form a model: allowed.
  }
}

void fuzz(const std::string& format, const std::vector<std::vector<std::string>>& seeds, const Reader& read,
          int iterations, unsigned seed) {
  Mutator mutator(seed);
  std::mt19937 choose(seed * 7 + 1);
  int accepted = 0, rejected = 0;
  // The unmodified seeds must be valid.
  for (const auto& files : seeds) {
    std::vector<TextSource> sources;
    for (size_t k = 0; k < files.size(); ++k)
      sources.emplace_back(format + std::to_string(k), files[k]);
    ASSERT_NO_THROW(read(sources)) << format;
  }
  for (int it = 0; it < iterations; ++it) {
    const auto& files = seeds[choose() % seeds.size()];
    const size_t target = choose() % files.size();
    std::vector<TextSource> sources;
    for (size_t k = 0; k < files.size(); ++k)
      sources.emplace_back(format + std::to_string(k),
                           k == target ? mutator.mutate(files[k]) : files[k]);
    try {
      read(sources);
      ++accepted;
    } catch (const InputError&) {
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << format << " iteration " << it << ": " << typeid(e).name() << ": " << e.what()
                    << "\n--- input ---\n"
                    << sources[target].text().substr(0, 2000);
      return;
    }
  }
  // Both outcomes occur: the mutations are neither all harmless nor all fatal.
  EXPECT_GT(accepted, 0) << format;
  EXPECT_GT(rejected, iterations / 4) << format;
}

std::string model_text(const StructuralModel& m, void (*write)(const StructuralModel&, std::ostream&, int)) {
  std::ostringstream out;
  write(m, out, 17);
  return out.str();
}

std::string volume_text(const VolumeMesh& m, void (*write)(const VolumeMesh&, std::ostream&, int)) {
  std::ostringstream out;
  write(m, out, 17);
  return out.str();
}

StructuralModel small_model() { return build_model(test::lattice_box(2, true)); }

constexpr int kIterations = 4000;

TEST(MutationFuzz, Tsurf) {
  const std::string handmade =
      "GOCAD TSurf 1\nHEADER {name: a}\nGOCAD_ORIGINAL_COORDINATE_SYSTEM\nZPOSITIVE Depth\n"
      "END_ORIGINAL_COORDINATE_SYSTEM\nPROPERTY_CLASS_HEADER Z {\nkind: Depth\n}\nTFACE\n"
      "PVRTX 0 0 0 0 1 CNXYZ\nPVRTX 1 1 0 0 2 CNXYZ\nVRTX 2 0 1 0\nATOM 3 1\nTRGL 0 1 2\nTFACE\nVRTX 4 1 1 0\n"
      "TRGL 3 4 2\nBSTONE 1\nBORDER 5 1 2\nEND\nGOCAD PLine 1\nHEADER {\nname: l\n}\nEND\n";
  fuzz("ts", {{model_text(small_model(), write_tsurf)}, {handmade}},
       [](const auto& s) { model_read(read_tsurf, s[0]); }, kIterations, 11);
}

TEST(MutationFuzz, Model3d) {
  fuzz("ml", {{model_text(small_model(), write_model3d)}}, [](const auto& s) { model_read(read_model3d, s[0]); },
       kIterations, 12);
}

TEST(MutationFuzz, Obj) {
  const std::string handmade =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2//1 3\ng quad\nf -4 -3 -1 -2\n"
      "o other\nusemtl m\nf 1 3 4\n";
  fuzz("obj", {{model_text(small_model(), write_obj)}, {handmade}},
       [](const auto& s) { model_read(read_obj, s[0]); }, kIterations, 13);
}

TEST(MutationFuzz, Medit) {
  const std::string quads =
      "MeshVersionFormatted 1\nDimension\n3\nVertices 4\n0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n"
      "Quadrilaterals\n1\n1 2 3 4 7\nEdges 1 1 2 0\nCorners 1 1\nEnd\n";
  fuzz("mesh", {{model_text(small_model(), write_medit)}, {quads}, {volume_text(test::cube_tet_mesh(), write_medit_volume)}},
       [](const auto& s) { model_read(read_medit, s[0]); }, kIterations, 14);
  fuzz("mesh-volume", {{volume_text(test::cube_tet_mesh(), write_medit_volume)}},
       [](const auto& s) { read_medit_volume(s[0]); }, kIterations, 15);
}

TEST(MutationFuzz, Vtu) {
  fuzz("vtu", {{model_text(small_model(), write_vtu)}}, [](const auto& s) { model_read(read_vtu, s[0]); },
       kIterations, 16);
  fuzz("vtu-volume", {{volume_text(test::cube_tet_mesh(), write_vtu_volume)}},
       [](const auto& s) { read_vtu_volume(s[0]); }, kIterations, 17);
}

TEST(MutationFuzz, Gmsh) {
  fuzz("msh", {{model_text(small_model(), write_msh)}}, [](const auto& s) { model_read(read_msh, s[0]); },
       kIterations, 18);
  fuzz("msh-volume", {{volume_text(test::cube_tet_mesh(), write_msh_volume)}},
       [](const auto& s) { read_msh_volume(s[0]); }, kIterations, 19);
}

TEST(MutationFuzz, Tetgen) {
  const VolumeMesh m = test::cube_tet_mesh();
  std::ostringstream node, ele, face;
  write_tetgen_node(m, node, 17);
  write_tetgen_ele(m, ele);
  write_tetgen_face(m, face);
  fuzz("tetgen", {{node.str(), ele.str(), face.str()}},
       [](const auto& s) { read_tetgen(s[0], s[1], &s[2]); }, kIterations, 20);
}

}  // namespace
}  // namespace voroseal
