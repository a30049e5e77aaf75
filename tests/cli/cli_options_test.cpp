// Numeric options are bounded where they are parsed (the bound in --help); what a value within
// the bounds would cost is estimated against the memory before any work.
#include <gtest/gtest.h>

#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_run.h"

namespace voroseal::test {
namespace {

int thread_limit() {
  const unsigned hardware = std::thread::hardware_concurrency();
  return 4 * static_cast<int>(hardware > 0 ? hardware : 1);
}

TEST(CliOptions, ThreadsAreBoundedByFourTimesTheHardwareThreads) {
  const CliDir dir("cli_threads");
  const std::string model = dir / "box.ts";
  write_box_model(model);
  for (const std::string& threads : std::vector<std::string>{"100000", "1000", "1.8e308", "-1",
                                                             std::to_string(thread_limit() + 1)}) {
    const CliResult r = run_voroseal({"--threads", threads, "check", model});
    EXPECT_EQ(r.exit_code, 2) << threads << ": " << r.err;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
  }
  const CliResult at_limit =
      run_voroseal({"--threads", std::to_string(thread_limit()), "check", model});
  EXPECT_EQ(at_limit.exit_code, 0) << at_limit.err;
}

TEST(CliOptions, HelpShowsTheBoundsOfNumericOptions) {
  const CliResult top = run_voroseal({"--help"});
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_NE(top.out.find("0 to " + std::to_string(thread_limit())), std::string::npos) << top.out;
  const CliResult remesh = run_voroseal({"remesh", "--help"});
  EXPECT_EQ(remesh.exit_code, 0);
  EXPECT_NE(remesh.out.find("1 to 2147483647"), std::string::npos) << remesh.out;  // --seeds
  const CliResult modules = run_voroseal({"modules"});
  EXPECT_NE(modules.out.find("(1 to 2147483647)"), std::string::npos);
}

TEST(CliOptions, OutOfRangeModuleParametersAreBadCommandLines) {
  const CliDir dir("cli_range");
  const std::string model = dir / "box.ts";
  write_box_model(model);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"remesh", model, "--seeds", "0"},
        {"remesh", model, "--seeds", "99999999999999"},
        {"remesh", model, "--edge-length", "nan"},
        {"remesh", model, "--edge-length", "1e400"},
        {"stats", model, "--samples", "-5"},
        {"check", model, "--examples", "1e9"},
        {"tetmesh", model, "--quality", "1000"},
        {"--max-memory", "lots", "check", model},
        {"check", model, "--weld-tolerance", "5"}}) {
    const CliResult r = run_voroseal(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << " " << args[2] << ": " << r.err;
  }
}

TEST(CliOptions, RunsThatCannotFitInMemoryAreRefusedBeforeTheyStart) {
  const CliDir dir("cli_memory");
  const std::string model = dir / "box.ts";
  write_box_model(model);
  const std::string out = dir / "out.obj";
  // 200 million seeds, an edge length giving as many on this unit box, 2e9 sample points.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"remesh", model, "--seeds", "200000000", "-o", out},
        {"remesh", model, "--edge-length", "0.0001", "-o", out},
        {"stats", model, "--ref", model, "--samples", "2000000000"},
        // A unit box under tets of 1e-12 (the bound alone would have TetGen run for hours).
        {"tetmesh", model, "--max-volume", "1e-12", "-o", dir / "out.mesh"}}) {
    const CliResult r = run_voroseal(args);
    EXPECT_EQ(r.exit_code, 2) << args[2] << ": " << r.err;
    EXPECT_NE(r.err.find("of memory"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  }
  // A budget set by hand is the one compared with.
  const CliResult tight =
      run_voroseal({"--max-memory", "1K", "remesh", model, "--seeds", "200", "-o", out});
  EXPECT_EQ(tight.exit_code, 2) << tight.err;
  EXPECT_NE(tight.err.find("--max-memory (1 KB)"), std::string::npos) << tight.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"box.ts"});
}

// --size is repeatable: every rule given applies, and the report says so per surface.
TEST(CliOptions, EveryGivenSizeRuleApplies) {
  CliDir dir("cli_size_rules");
  const std::string model = dir / "box.ts";
  write_box_model(model, 6);
  const CliResult r =
      run_voroseal({"--json", "-q", "remesh", model, "--seeds", "300", "-o", dir / "r.obj",
                    "--size", "horizon=0.1", "--size", "zmin=0.12,zmax=0.12"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  int sized = 0;
  for (const nlohmann::json& s : report.at("remesh").at("sizes").at("surfaces")) {
    const std::string name = s.at("name");
    const double asked = s.at("asked");
    if (name == "horizon") {
      EXPECT_EQ(asked, 0.1);
    }
    if (name == "zmin" || name == "zmax") {
      EXPECT_EQ(asked, 0.12);
    }
    sized += name == "horizon" || name == "zmin" || name == "zmax";
  }
  EXPECT_EQ(sized, 3);
  const CliResult bad =
      run_voroseal({"remesh", model, "--seeds", "300", "-o", dir / "s.obj", "--size", "x=1"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--size: 'x' names no surface"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace voroseal::test
