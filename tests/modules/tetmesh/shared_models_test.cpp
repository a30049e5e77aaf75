// The shared RING models as given (no remeshing): TetGen succeeds keeping the surfaces (Y), one
// region id per model region, every model triangle a tet face, region volumes equal to the
// enclosed volumes within 1e-6. No dihedral bound: the raw inputs hold needle triangles that no
// tet mesh keeping the surfaces can fix; the figures are printed for the record ([figures]).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "io/model_io.h"
#include "modules/tetmesh/tetrahedralize.h"
#include "framework/geometry/volume_quality.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

struct SharedCase {
  const char* file;
  double feature_angle_deg;  // for soups whose box sides share a group
  /// Model triangles TetGen 1.5 is known to split despite Y. modelA2: the two needle triangles
  /// (0.16° and 0.31°, 5.8 km long) of fault f2_model3_0/4 at corner vertex 37 share an edge
  /// TetGen cannot recover by flips; it puts one Steiner point on it and fails to remove it
  /// (with every Y variant). Any other split is a regression.
  int known_split_triangles = 0;
  /// Radius-edge bound of the run. The raw inputs' needle triangles make TetGen's refinement
  /// slow under Y (A2, A4, A6: 5-10 s in refinement alone) without improving them, so those
  /// are tested without refinement (`pAYJQ`) to keep the suite fast; the small ones with the
  /// defaults (`pq1.5/10AYJQ` for the needle-filled ones, see tetrahedralize();
  /// geomodel3d_only gets `o/150`). Figures with the defaults for all: see the tetmesh report.
  double radius_edge_ratio = TetmeshOptions{}.radius_edge_ratio;
  /// TetGen attempts (facet orders). modelA2's split is the same in every order tried (the
  /// reversed one and most shuffles crash), so one attempt keeps its test short; modelA4 needs
  /// the retry: TetGen 1.5 fails an assertion with the file's facet order under Y.
  int attempts = TetmeshOptions{}.attempts;
};

void PrintTo(const SharedCase& c, std::ostream* os) { *os << c.file; }

class SharedRingModel : public testing::TestWithParam<SharedCase> {};

TEST_P(SharedRingModel, TetgenMeshesEveryRegionConformally) {
  VOROSEAL_REQUIRE_SHARED(path, std::string("ring/") + GetParam().file);
  ReadOptions read;
  read.build.feature_angle_deg = GetParam().feature_angle_deg;
  const StructuralModel model = read_model(path, read);
  ASSERT_FALSE(model.regions.empty());

  Logger log(LogLevel::Quiet);
  TetmeshRun run;
  const auto start = std::chrono::steady_clock::now();
  TetmeshOptions options;
  options.radius_edge_ratio = GetParam().radius_edge_ratio;
  options.attempts = GetParam().attempts;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const VolumeQuality q = measure_volume(mesh);

  // The model TetGen meshed, with the points the smoothing slid where they went.
  const StructuralModel& meshed = run.refined_model ? *run.refined_model : model;
  EXPECT_EQ(q.regions, static_cast<int>(model.regions.size()));
  EXPECT_EQ(q.nonpositive_tets, 0);
  EXPECT_LE(model_triangles_not_in_tets(meshed, mesh).size(),
            static_cast<size_t>(GetParam().known_split_triangles));
  EXPECT_EQ(q.nonconforming_triangles, 0);  // the output triangles (split or not) are tet faces
  EXPECT_LE(run.split_facets, GetParam().known_split_triangles);
  double max_error = 0;
  ASSERT_EQ(q.region_volume.size(), model.regions.size());
  for (size_t r = 0; r < model.regions.size(); ++r) {
    const double enclosed = -meshed.signed_volume(meshed.regions[r].sides);
    const double error = std::abs(q.region_volume[r] - enclosed) / enclosed;
    max_error = std::max(max_error, error);
    EXPECT_LT(error, 1e-6) << "region " << model.regions[r].name << ": " << q.region_volume[r] << " vs " << enclosed;
    // The slides keep the surfaces within a hundredth of an edge: the volumes barely change.
    const double given = -model.signed_volume(model.regions[r].sides);
    EXPECT_NEAR(enclosed, given, 1e-3 * given) << "region " << model.regions[r].name;
  }
  std::fprintf(stderr,
               "[figures] %s (-%s): %d triangles, %zu regions, %.2f s (PLC %.2f s, TetGen %.2f s), %ld tets, %ld vertices "
               "(%d Steiner), %d split triangles, %d attempts, min dihedral %.3f deg, max dihedral %.2f deg, max radius-edge %.3g, "
               "max relative volume error %.2e\n",
               GetParam().file, run.switches.c_str(), model.num_triangles(), model.regions.size(), seconds, run.plc_seconds,
               run.tetgen_seconds, q.tets, q.vertices, run.steiner_points, run.split_facets, run.attempts, q.min_dihedral_deg, q.max_dihedral_deg,
               q.max_radius_edge, max_error);
  RecordProperty("seconds", std::to_string(seconds));
  RecordProperty("tets", std::to_string(q.tets));
  RecordProperty("min_dihedral_deg", std::to_string(q.min_dihedral_deg));
}

INSTANTIATE_TEST_SUITE_P(AsGiven, SharedRingModel,
                         testing::Values(SharedCase{"geomodel3d_only.ml", 0}, SharedCase{"modelA1.ml", 0},
                                         SharedCase{"modelA2.ml", 0, 2, 0.0, 1}, SharedCase{"modelA4.ml", 0, 0, 0.0},
                                         SharedCase{"CloudSpin_fixed.ml", 0},
                                         SharedCase{"modelA6.mesh", 45, 0, 0.0}),
                         [](const testing::TestParamInfo<SharedCase>& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace voroseal
