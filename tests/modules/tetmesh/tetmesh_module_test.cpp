#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "framework/core/error.h"
#include "framework/host/registry.h"
#include "framework/model/model_builder.h"
#include "tests/support/module_harness.h"
#include "tests/support/test_models.h"

void voroseal_register_tetmesh(voroseal::ModuleRegistry& registry);

namespace voroseal {
namespace {

TEST(TetmeshModule, SetsTheVolumeAndReport) {
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(4, true)));
  module.run(context, Parameters(module.parameters(), {{"quality", "1.4"}}));
  ASSERT_TRUE(context.volume);
  const auto& report = context.report.at("tetmesh");
  EXPECT_EQ(report.at("switches"),
            report.at("polished").get<bool>() ? "pq1.4/15o/150AYJQ" : "pq1.4/10o/150AYJQ");
  // The dihedral histogram: cumulative counts, TetGen's first mesh and the output.
  const auto& below = report.at("tets_below_deg");
  for (const char* when : {"tetgen", "final"}) {
    long previous = 0;
    for (const char* mark : {"5", "10", "15", "20", "30"}) {
      const long n = below.at(when).at(mark).get<long>();
      EXPECT_GE(n, previous) << when << " " << mark;
      previous = n;
    }
  }
  EXPECT_LE(below.at("final").at("15").get<long>(), below.at("tetgen").at("15").get<long>());
  EXPECT_EQ(report.at("tets").get<long>(), static_cast<long>(context.volume->tets.size()));
  EXPECT_EQ(report.at("regions_meshed"), 2);
  EXPECT_EQ(report.at("nonconforming_triangles"), 0);
  EXPECT_EQ(report.at("nonpositive_tets"), 0);
  EXPECT_LT(report.at("max_relative_volume_error").get<double>(), 1e-6);
  EXPECT_GE(report.at("min_dihedral_deg").get<double>(), 5.0);
  ASSERT_EQ(report.at("regions").size(), 2u);
  EXPECT_NEAR(report.at("regions")[0].at("enclosed_volume").get<double>(), 0.5, 1e-12);
  EXPECT_FALSE(report.contains("output"));
}

TEST(TetmeshModule, RegionSizeBoundsTheNamedRegionAndReportsIt) {
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(2, true)));
  const std::string name = context.model->regions[1].name;
  const double h = 0.2;  // a regular tet of edge h: volume h^3 / (6 sqrt 2)
  module.run(context,
             Parameters(module.parameters(), {{"region-size", name + "=" + std::to_string(h)}}));
  const auto& regions = context.report.at("tetmesh").at("regions");
  ASSERT_EQ(regions.size(), 2u);
  const double bound = h * h * h / (6.0 * std::sqrt(2.0));
  EXPECT_NEAR(regions[1].at("volume_bound").get<double>(), bound, 1e-12);
  EXPECT_LE(regions[1].at("largest_tet").get<double>(), bound * (1 + 1e-9));
  EXPECT_TRUE(regions[0].at("volume_bound").is_null());
  EXPECT_GT(regions[0].at("largest_tet").get<double>(), bound);
  // A name that is no region: an error listing the names there are.
  try {
    module.run(context, Parameters(module.parameters(), {{"region-size", "Reservoir=0.1"}}));
    FAIL() << "an unknown region was accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      module.run(context, Parameters(module.parameters(), {{"region-size", name + "=-1"}})),
      ParameterError);
}

TEST(TetmeshModule, SurfaceSizesAndSizeFieldReachTetGen) {
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(4, true)));
  module.run(context, Parameters(module.parameters(), {}));
  const long plain = context.report.at("tetmesh").at("tets").get<long>();
  module.run(context, Parameters(module.parameters(), {{"surface-sizes", true}}));
  EXPECT_NE(context.report.at("tetmesh").at("switches").get<std::string>().find('m'),
            std::string::npos);
  EXPECT_GT(context.report.at("tetmesh").at("tets").get<long>(), plain);
  // A size field file (file coordinates): finer again near its point.
  const std::string field = ::testing::TempDir() + "tetmesh_size_field.xyz";
  {
    std::FILE* f = std::fopen(field.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, "0.5 0.5 0.5 0.05\n");
    std::fclose(f);
  }
  module.run(context, Parameters(module.parameters(), {{"size-field", field}}));
  EXPECT_GT(context.report.at("tetmesh").at("tets").get<long>(), plain);
  EXPECT_THROW(
      module.run(context, Parameters(module.parameters(), {{"size-field", field + ".missing"}})),
      InputError);
  EXPECT_THROW(module.run(context, Parameters(module.parameters(),
                                              {{"size-field", field}, {"gradation", 1.0}})),
               ParameterError);
  std::remove(field.c_str());
}

TEST(TetmeshModule, ReportsTheSurfaceBisectionAndRejectsItsBadOptions) {
  // A layer 0.02 thick under 0.125 triangles: the report counts the bisected edges and checks
  // conformity against the triangles TetGen got; options out of range are parameter errors.
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::thin_layer_box(8, 0.02)));
  module.run(context, Parameters(module.parameters(), {}));
  const auto& report = context.report.at("tetmesh");
  EXPECT_GE(report.at("surface_bisection").at("rounds").get<int>(), 1);
  EXPECT_GT(report.at("surface_bisection").at("edges").get<int>(), 0);
  EXPECT_GT(report.at("surface_bisection").at("triangles").get<int>(), context.model->num_triangles());
  EXPECT_EQ(report.at("nonconforming_triangles"), 0);
  EXPECT_LT(report.at("max_relative_volume_error").get<double>(), 1e-6);
  module.run(context, Parameters(module.parameters(), {{"refine-surface-below", 0.0}}));
  EXPECT_EQ(context.report.at("tetmesh").at("surface_bisection").at("edges"), 0);
  EXPECT_EQ(context.report.at("tetmesh").at("surface_bisection").at("triangles"), context.model->num_triangles());
  EXPECT_THROW(module.run(context, Parameters(module.parameters(), {{"refine-surface-below", -1.0}})),
               ParameterError);
  EXPECT_THROW(module.run(context, Parameters(module.parameters(), {{"refine-surface-rounds", 11}})), ParameterError);
}

TEST(TetmeshModule, NoTetIsFlatterThanTheThinnestWedgeItReports) {
  // A pinch-out at 3 degrees: the tets on the pinch-out line share its 3 degrees.
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::pinch_out_prism(3.0)));
  module.run(context, Parameters(module.parameters(), {}));
  const auto& report = context.report.at("tetmesh");
  ASSERT_TRUE(report.at("thinnest_wedge_deg").is_number());
  EXPECT_NEAR(report.at("thinnest_wedge_deg").get<double>(), 3.0, 1e-9);
  EXPECT_EQ(report.at("nonconforming_triangles"), 0);
  EXPECT_LE(report.at("min_dihedral_deg").get<double>(), 3.0 + 1e-9);
  EXPECT_GT(report.at("min_dihedral_deg").get<double>(), 0.0);
  // A box cut by a horizon has no wedge under 30 degrees.
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(4, true)));
  module.run(context, Parameters(module.parameters(), {}));
  EXPECT_TRUE(context.report.at("tetmesh").at("thinnest_wedge_deg").is_null());
}

TEST(TetmeshModule, WarnsAboutNearlyFlatTets) {
  // A pinch-out at 0.5 degrees: the tets along the pinch-out line are that flat.
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh", LogLevel::Warning, log);
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::pinch_out_prism(0.5)));
  module.run(context, Parameters(module.parameters(), {}));
  const auto& report = context.report.at("tetmesh");
  EXPECT_LT(report.at("min_dihedral_deg").get<double>(), 0.5 + 1e-9);
  EXPECT_GT(report.at("nearly_flat_tets").get<long>(), 0);
  std::rewind(log);
  std::string text(4096, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), log));
  EXPECT_NE(text.find("nearly flat tets"), std::string::npos) << text;
  // At 3 degrees none is (the harness logs to `log` until the end).
  context.model = std::make_shared<StructuralModel>(build_model(test::pinch_out_prism(3.0)));
  module.run(context, Parameters(module.parameters(), {}));
  EXPECT_EQ(context.report.at("tetmesh").at("nearly_flat_tets").get<long>(), 0);
  std::fclose(log);
}

TEST(TetmeshModule, NamesTheBorderGapItsFlattestTetsLieIn) {
  // A fault border leaving the horizon at 2 degrees, meshed without bisection or smoothing
  // (which open the gap here): the flattest tets lie in the gap, and the warning names it
  // rather than a layer. A steep border gives no such line.
  for (const double angle : {2.0, 40.0}) {
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh", LogLevel::Warning, log);
    const Module& module = harness.module;
    Context& context = harness.context;
    context.model =
        std::make_shared<StructuralModel>(build_model(test::fault_leaving_horizon_box(angle)));
    module.run(context, Parameters(module.parameters(),
                                   {{"refine-surface-below", "0"}, {"smooth", "false"}}));
    std::rewind(log);
    std::string text(8192, '\0');
    text.resize(std::fread(text.data(), 1, text.size(), log));
    std::fclose(log);
    const bool named =
        text.find("in the gap between the free border of fault") != std::string::npos;
    EXPECT_EQ(named, angle < 10.0) << text;
    // The report gives the gap's angle whatever the tets (up to 30 degrees).
    const auto& gap = context.report.at("tetmesh").at("thinnest_border_gap_deg");
    if (angle < 30.0) {
      ASSERT_TRUE(gap.is_number());
      EXPECT_NEAR(gap.get<double>(), angle, 1e-9);
    } else {
      EXPECT_TRUE(gap.is_null());
    }
  }
}

TEST(TetmeshModule, WritesTheOutputAndRefusesToOverwriteTheInput) {
  test::ModuleHarness harness(voroseal_register_tetmesh, "tetmesh");
  const Module& module = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(2, true)));
  const auto dir = std::filesystem::temp_directory_path() / ("voroseal_tetmesh_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "box.mesh").string();
  module.run(context, Parameters(module.parameters(), {{"output", out}}));
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_GT(std::filesystem::file_size(out), 0u);
  EXPECT_EQ(context.report.at("tetmesh").at("output"), out);
  // The input of the run is protected.
  context.input_path = out;
  EXPECT_ANY_THROW(module.run(context, Parameters(module.parameters(), {{"output", out}})));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace voroseal
