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
  // The same with stderr in the output.
  std::string voroseal_messages(const std::string& arguments) const {
    return "VOROSEAL_PLUGIN_PATH='" + plugin_path_ + "' '" VOROSEAL_EXECUTABLE "' " + arguments +
           " 2>&1";
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
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

// The rows of a summary.json without the timings, which differ from one execution to the next.
json rows_without_times(const json& summary) {
  json rows = summary.at("runs");
  for (json& row : rows)
    for (auto it = row.begin(); it != row.end();)
      it = it.key().rfind("time_", 0) == 0 ? row.erase(it) : std::next(it);
  return rows;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(CliStudy, ShardsResumeAndMergeGiveTheSummaryOfTheWholeStudy) {
  // 2 models x 10 offsets: 20 runs.
  const std::string study = write_study(
      {{"name", "twenty"},
       {"models",
        {test::bundled_model("folded_layers.ts"), test::bundled_model("faulted_layers.ts")}},
       {"steps",
        {{{"module", "example-offset"}, {"parameters", {{"dz", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}}}}}}},
       {"write", {"model.obj"}},
       {"picture", {{"width", 80}, {"height", 60}}}});
  ASSERT_EQ(shell(voroseal("--quiet run '" + study + "' -o '" + path("whole") + "'")).exit_code, 0);
  std::string shards;
  for (int i = 1; i <= 4; ++i) {
    const std::string folder = path("shard" + std::to_string(i));
    const Result r = shell(voroseal("--quiet --json run '" + study + "' --shard " +
                                    std::to_string(i) + "/4 -o '" + folder + "'"));
    ASSERT_EQ(r.exit_code, 0) << i;
    const json rows = json::parse(r.out).at("runs");
    ASSERT_EQ(rows.size(), 5u);
    for (const json& row : rows) EXPECT_EQ((row.at("run").get<int>() - 1) % 4, i - 1);
    shards += " '" + folder + "'";
  }
  // Shard 2 again with --resume: its runs are complete, their rows come from run.json.
  const json before = read_json(path("shard2/summary.json"));
  Result r = shell(voroseal("--quiet --json run '" + study + "' --shard 2/4 --resume -o '" +
                            path("shard2") + "'"));
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(json::parse(r.out).at("runs"), before.at("runs")) << "timings included: nothing ran";

  r = shell(voroseal("--quiet --json run --merge" + shards + " -o '" + path("merged") + "'"));
  ASSERT_EQ(r.exit_code, 0);
  const json merged = json::parse(r.out);
  EXPECT_EQ(merged.at("runs_total"), 20);
  EXPECT_EQ(merged, read_json(path("merged/summary.json")));
  EXPECT_EQ(rows_without_times(merged), rows_without_times(read_json(path("whole/summary.json"))));
  EXPECT_EQ(merged.at("columns"), read_json(path("whole/summary.json")).at("columns"));
  const std::string html = read_file(path("merged/report.html"));
  EXPECT_NE(html.find("src=\"../shard4/faulted_layers/dz=9/picture.png\""), std::string::npos);
  EXPECT_NE(html.find("<h1>Study twenty</h1>"), std::string::npos);

  // A shard twice, or a study file with --merge: exit 2, naming the problem.
  r = shell(voroseal_messages("run --merge '" + path("shard1") + "' '" + path("shard1") + "' -o '" +
                              path("m2") + "'"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("found twice"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("a folder given twice"), std::string::npos) << r.out;
  r = shell(voroseal_messages("run '" + study + "' --merge '" + path("shard1") + "'"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("--merge"), std::string::npos) << r.out;
  // Three shards of four: a summary of 15 runs, exit 1, the missing ones named.
  r = shell(voroseal_messages("--quiet run --merge '" + path("shard1") + "' '" + path("shard2") +
                              "' '" + path("shard4") + "' -o '" + path("m3") + "'"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("no result for run 3, 7, 11, 15, 19 (of 20)"), std::string::npos) << r.out;
  EXPECT_EQ(read_json(path("m3/summary.json")).at("runs").size(), 15u);
}

TEST_F(CliStudy, BadShardOnlyEmitAndMergeOptionsExitWith2NamingTheOption) {
  const std::string study = write_study(
      {{"models", "a.ts"},
       {"steps", {{{"module", "example-offset"}, {"parameters", {{"dx", {1, 2, 3}}}}}}}});
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--shard 4/3", "--shard"},
      {"--shard 0/3", "--shard"},
      {"--shard x", "--shard"},
      {"--shard 1/0", "--shard"},
      {"--only 4", "--only"},
      {"--only 0", "--only"},
      {"--only x", "--only"},
      {"--shard 1/2 --only 1", "--only"},
      {"--emit make wf", "--emit"},
      {"--emit snakemake", "--emit"},
      {"--emit snakemake wf --shard 1/2", "--shard"}};
  for (const auto& [options, name] : cases) {
    const Result r = shell(voroseal_messages("run '" + study + "' " + options));
    EXPECT_EQ(r.exit_code, 2) << options << ": " << r.out;
    EXPECT_NE(r.out.find(name), std::string::npos) << options << ": " << r.out;
  }
  Result r = shell(voroseal_messages("run"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("study file"), std::string::npos) << r.out;
  r = shell(voroseal_messages("run --merge '" + path("absent") + "'"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("not a folder"), std::string::npos) << r.out;
  // A shard's dry run lists its runs only.
  r = shell(voroseal("--json run --dry-run '" + study + "' --shard 2/2"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(json::parse(r.out).at("runs").size(), 1u);
  EXPECT_EQ(json::parse(r.out).at("runs")[0].at("run"), 2);
}

// The study emitted as a Snakemake workflow and run with `snakemake -j2` gives the summary
// `voroseal run` gives, and the same files. Skipped when snakemake is not installed.
TEST_F(CliStudy, SnakemakeWorkflowGivesTheSummaryOfVorosealRun) {
  if (shell("snakemake --version >/dev/null 2>&1").exit_code != 0)
    GTEST_SKIP() << "snakemake is not installed (Debian package snakemake)";
  const std::string study = write_study(
      {{"name", "snake"},
       {"models", {test::bundled_model("folded_layers.ts")}},
       {"steps",
        {{{"module", "remesh"}, {"parameters", {{"seeds", {200, 400}}, {"iterations", 10}}}},
         {{"module", "stats"}, {"parameters", {{"ref", "{model}"}, {"samples", 2000}}}}}},
       {"write", {"model.ml"}},
       {"picture", {{"width", 80}, {"height", 60}}}});
  ASSERT_EQ(shell(voroseal("--quiet --threads 1 run '" + study + "' -o '" + path("direct") + "'"))
                .exit_code,
            0);
  Result r =
      shell(voroseal_messages("--threads 1 --max-memory 2G run '" + study + "' -o '" +
                              path("snake") + "' --emit snakemake '" + path("workflow") + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string snakefile = read_file(path("workflow/Snakefile"));
  EXPECT_NE(snakefile.find("THREADS = int(config.get(\"threads\", 1))"), std::string::npos);
  EXPECT_NE(snakefile.find("MEM_MB = int(config.get(\"mem_mb\", 2048))"), std::string::npos);
  EXPECT_FALSE(fs::exists(path("snake"))) << "emitting runs nothing";

  r = shell("cd '" + path("workflow") + "' && snakemake -j2 --quiet 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json direct = read_json(path("direct/summary.json"));
  const json snake = read_json(path("snake/summary.json"));
  EXPECT_EQ(snake.at("runs_total"), 2);
  EXPECT_EQ(snake.at("columns"), direct.at("columns"));
  EXPECT_EQ(rows_without_times(snake), rows_without_times(direct));
  for (const char* run : {"folded_layers/seeds=200", "folded_layers/seeds=400"}) {
    const std::string model = std::string("/") + run + "/model.ml";
    EXPECT_EQ(read_file(path("snake") + model), read_file(path("direct") + model)) << run;
    EXPECT_FALSE(read_file(path("snake") + model).empty()) << run;
  }
  EXPECT_TRUE(fs::exists(path("snake/report.html")));
  // Nothing left to do the second time.
  r = shell("cd '" + path("workflow") + "' && snakemake -j2 -n 2>&1");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("Nothing to be done"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace voroseal
