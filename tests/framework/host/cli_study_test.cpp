// `voroseal run` end to end: the executable, a study file, a plugin from VOROSEAL_PLUGIN_PATH.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/test_models.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Result {
  int exit_code = -1;
  std::string out;
};

// Runs a shell command; returns its exit code and stdout.
Result shell(const std::string& command) {
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class CliStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("voroseal_cli_study_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    plugin_path_ = fs::path(VOROSEAL_EXAMPLE_PLUGIN).parent_path().string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write_study(const json& study) {
    const std::string path = (dir_ / "study.json").string();
    std::ofstream(path) << study.dump(2);
    return path;
  }
  std::string voroseal(const std::string& arguments) const {
    return "VOROSEAL_PLUGIN_PATH='" + plugin_path_ + "' '" VOROSEAL_EXECUTABLE "' " + arguments + " 2>/dev/null";
  }
  fs::path dir_;
  std::string plugin_path_;
};

TEST_F(CliStudy, RunsAPluginStepFromThePluginPathAndPrintsTheSummaryAsJson) {
  const std::string study = write_study({{"name", "cli"},
                                         {"models", {test::bundled_model("folded_layers.ts"), "missing.ts"}},
                                         {"steps", {{{"module", "example-offset"}, {"parameters", {{"dz", {0, 10}}}}}}},
                                         {"write", {"model.obj"}},
                                         {"picture", {{"width", 200}, {"height", 140}}}});
  const Result r = shell(voroseal("--quiet --json run '" + study + "' --output '" + (dir_ / "o").string() + "'"));
  EXPECT_EQ(r.exit_code, 1) << "a failed run (the missing model) gives exit code 1";
  const json summary = json::parse(r.out);  // stdout holds only the JSON summary
  EXPECT_EQ(summary.at("study"), "cli");
  EXPECT_EQ(summary.at("runs_total"), 4);
  EXPECT_EQ(summary.at("runs_ok"), 2);
  EXPECT_EQ(summary.at("runs_failed"), 2);
  EXPECT_EQ(summary.at("runs")[1].at("dz"), 10);
  EXPECT_EQ(summary.at("runs")[1].at("status"), "ok");
  EXPECT_EQ(summary.at("runs")[0].at("triangles"), 6786);
  for (const char* f : {"o/summary.csv", "o/summary.json", "o/report.html", "o/folded_layers/dz=10/model.obj",
                        "o/folded_layers/dz=10/picture.png", "o/folded_layers/dz=10/run.json", "o/missing/dz=0/run.json"})
    EXPECT_TRUE(fs::exists(dir_ / f)) << f;
}

TEST_F(CliStudy, DryRunListsTheRunsAndBadStudiesExitWith2) {
  const std::string study = write_study({{"models", {"a.ts", "b.ts"}},
                                         {"steps", {{{"module", "example-offset"}, {"parameters", {{"dx", {1, 2, 3}}}}}}}});
  Result r = shell(voroseal("--json run --dry-run '" + study + "'"));
  EXPECT_EQ(r.exit_code, 0);
  const json listing = json::parse(r.out);
  ASSERT_EQ(listing.at("runs").size(), 6u);
  EXPECT_EQ(listing.at("runs")[5].at("directory"), (fs::current_path() / "out/study/b/dx=3").string());
  EXPECT_EQ(listing.at("runs")[5].at("model"), (dir_ / "b.ts").string()) << "models are found beside the study";
  EXPECT_FALSE(fs::exists(fs::current_path() / "out/study")) << "a dry run writes nothing";

  write_study({{"models", "a.ts"}, {"steps", {"no-such-module"}}});
  EXPECT_EQ(shell(voroseal("run '" + study + "'")).exit_code, 2);
  std::ofstream(study) << "{ not json";
  EXPECT_EQ(shell(voroseal("run '" + study + "'")).exit_code, 2);
  EXPECT_EQ(shell(voroseal("run '" + (dir_ / "absent.json").string() + "'")).exit_code, 2);
}

TEST_F(CliStudy, PluginModulesBecomeSubcommandsAndABadLibraryIsReported) {
  Result r = shell(voroseal("modules"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("example-offset"), std::string::npos);
  // A library without the entry point on the path: an error on stderr, the rest still works.
  const std::string bad = fs::path(VOROSEAL_NOT_A_PLUGIN).parent_path().string();
  const std::string command = "VOROSEAL_PLUGIN_PATH='" + bad + ":" + plugin_path_ + "' '" VOROSEAL_EXECUTABLE
                              "' modules 2>&1";
  r = shell(command);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("not a voroseal plugin"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("example-offset"), std::string::npos);
  // The plugin's module as a subcommand, with the global --json after it.
  r = shell(voroseal("example-offset '" + test::bundled_model("folded_layers.ts") + "' --dz 5 --json"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(json::parse(r.out).at("example-offset").at("offset")[2], 5.0);
}

}  // namespace
}  // namespace voroseal
