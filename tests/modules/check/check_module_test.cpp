#include <gtest/gtest.h>

#include <memory>

#include "framework/core/error.h"
#include "framework/host/context.h"
#include "framework/host/registry.h"
#include "framework/model/model_builder.h"
#include "tests/support/module_harness.h"
#include "tests/support/test_models.h"

void voroseal_register_check(voroseal::ModuleRegistry& registry);

namespace voroseal {
namespace {

struct CheckRun {
  int exit_code;
  nlohmann::json report;
  std::string out;
};

CheckRun run_check(const SurfaceSoup& soup, const nlohmann::json& values) {
  test::ModuleHarness harness(voroseal_register_check, "check");
  const Module& check = harness.module;
  Context& context = harness.context;
  context.model = std::make_shared<StructuralModel>(build_model(soup));
  const Parameters parameters(check.parameters(), values);  // may throw: before capturing stdout
  testing::internal::CaptureStdout();
  check.run(context, parameters);
  const std::string out = testing::internal::GetCapturedStdout();
  return {context.exit_code, context.report["check"], out};
}

TEST(CheckModule, ExitCodeAndReport) {
  const CheckRun ok = run_check(test::lattice_box(2, true), nlohmann::json::object());
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.report["valid"], true);
  EXPECT_NE(ok.out.find("VALID"), std::string::npos);

  SurfaceSoup open = test::lattice_box(2, false);  // a hole in face xmax
  open.triangles.pop_back();
  open.triangle_group.pop_back();
  const CheckRun bad = run_check(open, {{"json", true}});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.report["valid"], false);
  // --json prints exactly the report object on stdout.
  EXPECT_EQ(nlohmann::json::parse(bad.out), bad.report);
}

TEST(CheckModule, ParametersReachTheChecks) {
  const CheckRun strict =
      run_check(test::lattice_box(2, false), {{"short-edge", "0.3"}, {"json", "true"}, {"examples", 2}});
  EXPECT_EQ(strict.exit_code, 1);
  for (const auto& c : strict.report["checks"])
    if (c["name"] == "short_edges") {
      EXPECT_GT(c["count"].get<int>(), 0);
      EXPECT_EQ(c["examples"].size(), 2u);
    }
  const CheckRun fast = run_check(test::lattice_box(2, false), {{"intersections", false}, {"json", true}});
  for (const auto& c : fast.report["checks"])
    if (c["name"] == "self_intersections") {
      EXPECT_EQ(c["details"]["tested"], false);
    }
  EXPECT_THROW(run_check(test::lattice_box(2, false), {{"min-angle", -1}}), ParameterError);
}

}  // namespace
}  // namespace voroseal
