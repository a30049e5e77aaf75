// Studies beyond one run of voroseal: shards of the run list, resuming a study whose runs are
// partly complete, and merging the run folders of several shards into one summary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "framework/core/error.h"
#include "framework/host/pipeline.h"
#include "framework/host/study_report.h"
#include "framework/host/study_results.h"
#include "framework/host/study_shard.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A step that counts how often it ran, fails when asked, and reports its value.
class CountingStep : public Module {
 public:
  explicit CountingStep(std::atomic<int>& calls) : calls_(calls) {}
  std::string name() const override { return "counting-step"; }
  std::string description() const override { return "test step"; }
  std::vector<ParameterSpec> parameters() const override {
    return {{"fail", ParameterType::Bool, false, "throw a MesherError"},
            {"value", ParameterType::Double, 0.0, "a number to sweep"},
            {"say", ParameterType::String, "", "unused text"}};
  }
  void run(Context& context, const Parameters& p) const override {
    ++calls_;
    if (p.get_bool("fail")) throw MesherError("asked to fail");
    context.report["counting-step"] = {{"value", p.get_double("value")}};
  }

 private:
  std::atomic<int>& calls_;
};

class StudyRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("voroseal_shards_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    registry_.add(std::make_unique<CountingStep>(calls_));
    // Two small sealed models: a box cut by a horizon, on two lattices.
    write_model(build_model(test::lattice_box(4, true)), path("box.ml"));
    write_model(build_model(test::lattice_box(6, true)), path("fine_box.ml"));
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // 2 models x 10 values = 20 runs, each writing a model and a small picture.
  Study twenty_runs(const std::string& output) const {
    return parse_study({{"name", "twenty"},
                        {"models", {path("box.ml"), path("fine_box.ml")}},
                        {"output", path(output)},
                        {"steps",
                         {{{"module", "counting-step"},
                           {"parameters", {{"value", {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}}}}}}},
                        {"write", {"model.obj"}},
                        {"picture", {{"width", 64}, {"height", 48}}}},
                       dir_.string(), path("twenty.json"));
  }

  StudyOutcome run(const Study& study, const StudyOptions& options = {}) {
    Logger log(LogLevel::Quiet);
    Progress progress(false);
    return run_study(registry_, study, options, log, progress);
  }

  fs::path dir_;
  std::atomic<int> calls_{0};
  ModuleRegistry registry_;
};

// The summary rows without the timings, which differ from one execution to the next.
json rows_without_times(const StudyOutcome& outcome) {
  json rows = summary_rows(outcome);
  for (json& row : rows)
    for (auto it = row.begin(); it != row.end();)
      it = it.key().rfind("time_", 0) == 0 ? row.erase(it) : std::next(it);
  return rows;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(StudyShard, ParsesIOfNAndNamesTheOptionOtherwise) {
  const StudyShard shard = parse_shard("3/4");
  EXPECT_EQ(shard.index, 3);
  EXPECT_EQ(shard.count, 4);
  EXPECT_EQ(parse_shard("1/1").count, 1);
  for (const char* bad : {"0/4", "5/4", "1/0", "a/b", "1-4", "", "1/", "/4", "-1/4", "1/4/2",
                          " 1/4", "1/99999999999"}) {
    try {
      parse_shard(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--shard: ", 0), 0u) << e.what();
    }
  }
}

TEST_F(StudyRuns, ShardsDealTheRunsOutInTurnAndCoverEachOnce) {
  const std::vector<StudyRun> runs = expand_study(twenty_runs("out"));
  ASSERT_EQ(runs.size(), 20u);
  for (const int count : {1, 3, 4, 7, 25}) {
    std::multiset<int> seen;
    size_t smallest = runs.size(), largest = 0;
    for (int index = 1; index <= count; ++index) {
      const std::vector<int> shard = shard_runs(runs, {index, count});
      for (const int r : shard) {
        EXPECT_EQ(r % count, index - 1) << "run " << r << " in shard " << index << "/" << count;
        seen.insert(r);
      }
      EXPECT_TRUE(std::is_sorted(shard.begin(), shard.end()));
      smallest = std::min(smallest, shard.size());
      largest = std::max(largest, shard.size());
    }
    EXPECT_EQ(seen.size(), runs.size()) << count << " shards";
    for (const StudyRun& r : runs) EXPECT_EQ(seen.count(r.index), 1u) << count << " shards";
    EXPECT_LE(largest - smallest, 1u) << "shards of " << count << " are balanced";
  }
  EXPECT_EQ(shard_runs(runs, {2, 4}), (std::vector<int>{1, 5, 9, 13, 17}));
}

TEST_F(StudyRuns, ResumeKeepsCompleteRunsAndRedoesTheOthers) {
  Study study =
      parse_study({{"name", "resume"},
                   {"models", path("box.ml")},
                   {"output", path("out")},
                   {"steps",
                    {{{"module", "counting-step"},
                      {"parameters", {{"fail", {false, true}}, {"value", {1, 2, 3, 4}}}}}}},
                   {"write", {"model.obj"}},
                   {"picture", false}},
                  dir_.string(), path("resume.json"));
  const StudyOutcome first = run(study);
  ASSERT_EQ(first.runs.size(), 8u);
  ASSERT_EQ(calls_, 8);
  ASSERT_EQ(first.failed, 4);  // fail=true: runs 5 to 8
  auto folder = [&](int r) { return first.runs[r].run.directory; };
  fs::remove(folder(0) + "/run.json");                            // killed before its end
  std::ofstream(folder(1) + "/run.json") << "{\"study\": \"res";  // a partial file
  fs::remove(folder(2) + "/model.obj");                           // an output gone
  // Run 4 (index 3) is complete and stays as it is.

  StudyOptions options;
  options.resume = true;
  const StudyOutcome second = run(study, options);
  EXPECT_EQ(calls_, 8 + 3 + 4) << "runs 1 to 3 and the failed runs are done again";
  ASSERT_EQ(second.runs.size(), 8u);
  EXPECT_EQ(second.failed, 4);
  EXPECT_EQ(second.runs[3].total_seconds, first.runs[3].total_seconds) << "taken from run.json";
  EXPECT_EQ(second.runs[3].measures, first.runs[3].measures);
  EXPECT_EQ(second.runs[3].outputs, first.runs[3].outputs);
  EXPECT_EQ(rows_without_times(second), rows_without_times(first));
  for (int r = 0; r < 3; ++r) EXPECT_TRUE(fs::exists(folder(r) + "/run.json")) << r;
  EXPECT_TRUE(fs::exists(folder(2) + "/model.obj"));

  // Everything complete: nothing runs. A changed study is another study: everything runs.
  run(study, options);
  EXPECT_EQ(calls_, 15 + 4);
  study.steps[0].parameters["say"] = "changed";
  run(study, options);
  EXPECT_EQ(calls_, 19 + 8);
}

TEST_F(StudyRuns, FourShardsMergeIntoTheSummaryOfTheWholeStudy) {
  const StudyOutcome whole = run(twenty_runs("whole"));
  ASSERT_EQ(whole.runs.size(), 20u);
  std::vector<std::string> shards;
  for (int i = 1; i <= 4; ++i) {
    StudyOptions options;
    options.runs = shard_runs(expand_study(twenty_runs("whole")), {i, 4});
    const StudyOutcome part = run(twenty_runs("shard" + std::to_string(i)), options);
    EXPECT_EQ(part.runs.size(), 5u);
    shards.push_back(path("shard" + std::to_string(i)));
  }
  EXPECT_EQ(calls_, 40);

  const MergedStudy merged = merge_study_results(shards, path("merged"));
  EXPECT_TRUE(merged.missing.empty());
  ASSERT_EQ(merged.outcome.runs.size(), 20u);
  EXPECT_EQ(merged.outcome.study.output, path("merged"));
  EXPECT_EQ(summary_columns(merged.outcome), summary_columns(whole));
  EXPECT_EQ(rows_without_times(merged.outcome), rows_without_times(whole));
  EXPECT_EQ(merged.outcome.exit_code(), 0);

  // One report whose links lead to the shards' files.
  write_study_reports(merged.outcome);
  const std::string html = read_text(path("merged/report.html"));
  EXPECT_EQ(json::parse(read_text(path("merged/summary.json"))).at("runs").size(), 20u);
  size_t sections = 0;
  for (size_t at = html.find("<section class=\"run\""); at != std::string::npos;
       at = html.find("<section class=\"run\"", at + 1))
    ++sections;
  EXPECT_EQ(sections, 20u);
  const RunOutcome& second = merged.outcome.runs[1];  // shard 2
  EXPECT_EQ(second.picture, "../shard2/box/value=2/picture.png");
  EXPECT_NE(html.find("src=\"../shard2/box/value=2/picture.png\""), std::string::npos);
  EXPECT_NE(html.find("href=\"../shard2/box/value=2/run.json\""), std::string::npos);
  for (const RunOutcome& r : merged.outcome.runs) {
    EXPECT_TRUE(fs::exists(path("merged") + "/" + r.picture)) << r.picture;
    for (const std::string& o : r.outputs) EXPECT_TRUE(fs::exists(path("merged") + "/" + o)) << o;
  }

  // Merged in place, one folder gives back its own summary, links unchanged.
  const MergedStudy again = merge_study_results({path("whole")}, path("whole"));
  EXPECT_EQ(rows_without_times(again.outcome), rows_without_times(whole));
  EXPECT_EQ(again.outcome.runs[1].picture, "box/value=2/picture.png");
}

TEST_F(StudyRuns, MergeRefusesDuplicatesAndOtherStudiesAndNamesMissingRuns) {
  const std::vector<StudyRun> runs = expand_study(twenty_runs("a"));
  StudyOptions first, second;
  first.runs = shard_runs(runs, {1, 2});
  second.runs = shard_runs(runs, {2, 2});
  run(twenty_runs("a"), first);
  run(twenty_runs("b"), second);

  auto merge_error = [&](const std::vector<std::string>& folders) -> std::string {
    try {
      merge_study_results(folders, path("merged"));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(merge_error({path("a"), path("a")}).find("run 1 found twice"), std::string::npos);
  // The same run in two folders (a shard run twice into different folders).
  fs::create_directories(path("a2/box"));
  fs::copy(path("a/box/value=1"), path("a2/box/value=1"), fs::copy_options::recursive);
  const std::string twice = merge_error({path("a"), path("a2")});
  EXPECT_NE(twice.find("run 1 found twice: " + path("a/box/value=1/run.json") + " and " +
                       path("a2/box/value=1/run.json")),
            std::string::npos)
      << twice;

  // The same run numbers in a study that differs: not merged with the first.
  Study other = twenty_runs("c");
  other.steps[0].parameters["say"] = "another study";
  run(other, second);
  const std::string error = merge_error({path("a"), path("c")});
  EXPECT_NE(error.find("another study than"), std::string::npos) << error;
  EXPECT_NE(error.find("\"steps\""), std::string::npos) << error;

  fs::create_directories(path("empty"));
  EXPECT_NE(merge_error({path("empty")}).find("no run.json"), std::string::npos);
  EXPECT_THROW(merge_study_results({path("absent")}, ""), InputError);
  std::ofstream(path("b/box/value=2/run.json")) << "{\"definition\": ";
  EXPECT_THROW(merge_study_results({path("b")}, ""), InputError);
  EXPECT_FALSE(fs::exists(path("merged"))) << "nothing is written by a merge that fails";

  // One shard alone: a summary of its runs, the others named as missing.
  const MergedStudy half = merge_study_results({path("a")}, path("merged"));
  EXPECT_EQ(half.outcome.runs.size(), 10u);
  std::vector<int> even;
  for (int n = 2; n <= 20; n += 2) even.push_back(n);
  EXPECT_EQ(half.missing, even);
}

}  // namespace
}  // namespace voroseal
