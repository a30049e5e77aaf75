#include "modules/stats/model_statistics.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "framework/host/context.h"
#include "framework/host/registry.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "tests/support/module_harness.h"
#include "tests/support/test_models.h"

void voroseal_register_stats(voroseal::ModuleRegistry& registry);

namespace voroseal {
namespace {

TEST(ModelStatistics, LatticeBoxByHand) {
  // n = 2 unit box with a horizon at mid-height: all 27 lattice points (the horizon holds the
  // centre), 6 * 8 + 8 triangles, all right isosceles (45°, 45°, 90°).
  const ModelStatistics s = measure_model(build_model(test::lattice_box(2, true)));
  EXPECT_EQ(s.vertices, 27);
  EXPECT_EQ(s.triangles, 56);
  EXPECT_EQ(s.surfaces, 11);
  EXPECT_EQ(s.regions, 2);
  EXPECT_NEAR(s.quality.min_angle_deg, 45.0, 1e-9);
  EXPECT_EQ(s.quality.pct_below_threshold, 0.0);
  const double q = 3.0 / (std::sqrt(3.0) * std::sqrt(2.0) * (2.0 + std::sqrt(2.0)) / 2.0);
  EXPECT_NEAR(s.quality.avg_q, q, 1e-12);
  EXPECT_NEAR(s.quality.min_q, q, 1e-12);
  EXPECT_NEAR(s.quality.area, 7.0, 1e-12);  // 6 faces + the horizon
  EXPECT_NEAR(s.bbox_diagonal, std::sqrt(3.0), 1e-12);
}

SurfaceSoup square(double z, const Vec3& offset = Vec3::Zero()) {
  SurfaceSoup s;
  s.source = "square";
  s.points = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
  for (Vec3& p : s.points) p += offset;
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.triangle_group = {0, 0};
  s.groups = {{"square", "square", SurfaceKind::Horizon, ""}};
  return s;
}

TEST(ModelStatistics, HausdorffOfLiftedSquareIsOneTenthBothWays) {
  // Far from the origin, as in UTM files: each model has its own local frame.
  const Vec3 utm(5e5, 4e6, 0);
  const StructuralModel a = build_model(square(0.0, utm)), b = build_model(square(0.1, utm));
  const FidelityStatistics f = hausdorff(a, b, 2000, 1);
  EXPECT_NEAR(f.distance.a_to_b.max, 0.1, 1e-9);
  EXPECT_NEAR(f.distance.b_to_a.max, 0.1, 1e-9);
  EXPECT_NEAR(f.distance.hausdorff, 0.1, 1e-9);
  EXPECT_NEAR(f.reference_diagonal, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(f.hausdorff_pct, 10.0 / std::sqrt(2.0), 1e-7);
  EXPECT_NEAR(f.area_ratio, 1.0, 1e-12);
  EXPECT_NEAR(f.distance.b_to_a.max_at.x(), 5e5, 2);  // file coordinates
  // A model against itself.
  EXPECT_NEAR(hausdorff(a, a, 500, 2).hausdorff_pct, 0.0, 1e-9);
}

TEST(ModelStatistics, JsonHasTheKeysScriptsRead) {
  const StructuralModel m = build_model(test::lattice_box(2, true));
  const ModelStatistics s = measure_model(m);
  const nlohmann::json plain = to_json(s);
  for (const char* key : {"vertices", "triangles", "surfaces", "contacts", "corners", "regions", "min_angle_deg",
                          "pct_triangles_angle_below_30", "avg_quality", "min_quality", "area", "bbox_diagonal"})
    EXPECT_TRUE(plain.contains(key)) << key;
  EXPECT_FALSE(plain.contains("hausdorff_pct"));
  const FidelityStatistics f = hausdorff(m, m, 1000, 1);
  const nlohmann::json with_ref = to_json(s, &f, &s);
  EXPECT_TRUE(with_ref.contains("hausdorff_pct"));
  EXPECT_EQ(with_ref["reference"]["triangles"], 56);
  const std::string table = to_table(s, &f, &s);
  EXPECT_NE(table.find("min angle"), std::string::npos);
  EXPECT_NE(table.find("Hausdorff"), std::string::npos);
}

TEST(StatsModule, TableJsonAndReference) {
  test::ModuleHarness harness(voroseal_register_stats, "stats");
  const Module& stats = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(square(0.0)));
  // A reference file: the lifted square, written as OBJ.
  const std::string ref = testing::TempDir() + "voroseal_stats_ref.obj";
  {
    std::ofstream out(ref);
    out << "v 0 0 0.1\nv 1 0 0.1\nv 1 1 0.1\nv 0 1 0.1\ng square\nf 1 2 3\nf 1 3 4\n";
  }
  const Parameters parameters(stats.parameters(), {{"ref", ref}, {"json", true}, {"samples", 1000}});
  testing::internal::CaptureStdout();
  stats.run(context, parameters);
  const std::string out = testing::internal::GetCapturedStdout();
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j, context.report["stats"]);
  EXPECT_NEAR(j["hausdorff_pct"].get<double>(), 10.0 / std::sqrt(2.0), 1e-7);
  EXPECT_EQ(j["triangles"], 2);
  std::remove(ref.c_str());
  // Text table without a reference.
  testing::internal::CaptureStdout();
  stats.run(context, Parameters(stats.parameters(), nlohmann::json::object()));
  const std::string table = testing::internal::GetCapturedStdout();
  EXPECT_NE(table.find("triangles"), std::string::npos);
  EXPECT_EQ(table.find("Hausdorff"), std::string::npos);
}

// A unit cube cut into the six Kuhn tetrahedra around its diagonal, in two regions of three.
VolumeMesh kuhn_cube() {
  VolumeMesh mesh;
  for (int k = 0; k < 8; ++k) mesh.vertices.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  // Paths 0 -> 7 through the cube's corners, one per permutation of the axes.
  const int axes[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (int i = 0; i < 6; ++i) {
    Tetrahedron t{0, axes[i][0], axes[i][0] + axes[i][1], 7};
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]], &d = mesh.vertices[t[3]];
    if ((b - a).dot((c - a).cross(d - a)) < 0) std::swap(t[1], t[2]);
    mesh.tets.push_back(t);
    mesh.tet_region.push_back(i < 3 ? 0 : 1);
  }
  mesh.region_names = {"lower", "upper"};
  return mesh;
}

TEST(StatsModule, VolumeMeshFigures) {
  test::ModuleHarness harness(voroseal_register_stats, "stats");
  const Module& stats = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(square(0.0)));
  context.volume = std::make_shared<VolumeMesh>(kuhn_cube());
  testing::internal::CaptureStdout();
  stats.run(context, Parameters(stats.parameters(), {{"json", true}}));
  const nlohmann::json j = nlohmann::json::parse(testing::internal::GetCapturedStdout());
  const nlohmann::json& v = j.at("volume");
  EXPECT_EQ(v["tets"], 6);
  EXPECT_EQ(v["regions"], 2);
  EXPECT_NEAR(v["total_volume"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(v["min_dihedral_deg"].get<double>(), 45.0, 1e-9);
  EXPECT_EQ(v["nonpositive_tets"], 0);
  ASSERT_EQ(v["region_volumes"].size(), 2u);
  for (const auto& r : v["region_volumes"]) EXPECT_NEAR(r["volume"].get<double>(), 0.5, 1e-12);

  // The same figures from a volume file given as the input.
  const std::string path = testing::TempDir() + "voroseal_stats_kuhn.mesh";
  write_volume_mesh(*context.volume, path);
  Context from_file(harness.log, harness.progress);
  from_file.input_path = path;
  from_file.model = context.model;
  testing::internal::CaptureStdout();
  stats.run(from_file, Parameters(stats.parameters(), nlohmann::json::object()));
  const std::string table = testing::internal::GetCapturedStdout();
  EXPECT_NE(table.find("6 tets"), std::string::npos) << table;
  std::remove(path.c_str());
}

// The Table-2 numbers agree with the referee meshreport on the RING models (numbers measured
// with meshreport 2024; see the check/stats report): min angle, % < 30°, average Q, area, bbox
// diagonal.
struct Referee {
  const char* file;
  long triangles;
  double min_angle, pct30, avg_q, area, diagonal;
};

void PrintTo(const Referee& r, std::ostream* os) { *os << r.file; }

class RingStatistics : public testing::TestWithParam<Referee> {};

TEST_P(RingStatistics, AgreeWithMeshreport) {
  const Referee& r = GetParam();
  VOROSEAL_REQUIRE_SHARED(path, std::string("ring/") + r.file);
  const ModelStatistics s = measure_model(read_model(path));
  EXPECT_EQ(s.triangles, r.triangles);
  EXPECT_NEAR(s.quality.min_angle_deg, r.min_angle, 1e-6 * std::max(1.0, r.min_angle) + 1e-9);
  EXPECT_NEAR(s.quality.pct_below_threshold, r.pct30, 1e-6);
  EXPECT_NEAR(s.quality.avg_q, r.avg_q, 1e-9);
  EXPECT_NEAR(s.quality.area, r.area, 1e-9 * r.area);
  EXPECT_NEAR(s.bbox_diagonal, r.diagonal, 1e-9 * r.diagonal);
}

INSTANTIATE_TEST_SUITE_P(
    Ring, RingStatistics,
    testing::Values(
        Referee{"modelA1.ml", 7932, 0.0340952590138, 27.7483610691, 0.624838395264, 1030199319.29, 19441.3029112},
        Referee{"modelA2.ml", 16346, 4.96071279202e-05, 72.8251560015, 0.385202084782, 1146387612.07, 19441.3059804},
        Referee{"modelA4.ml", 48903, 0.00178145923281, 84.710549455, 0.300436582171, 1121754413.92, 19441.3029112},
        Referee{"CloudSpin_fixed.ml", 30751, 0.00696775392839, 47.0911515073, 0.579692110643, 2100723802.39,
                23058.9156832},
        Referee{"geomodel3d_only.ml", 379, 4.5896679028, 41.4248021108, 0.627033847955, 131435.274512, 208.216833631},
        Referee{"modelA6.mesh", 55426, 0.000464679760936, 78.6670515642, 0.343041074396, 1143570110.1, 19441.3029112}),
    [](const testing::TestParamInfo<Referee>& info) {
      std::string name = info.param.file;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

}  // namespace
}  // namespace voroseal
