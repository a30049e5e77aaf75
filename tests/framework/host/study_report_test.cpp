#include "framework/host/study_report.h"

#include <gtest/gtest.h>

namespace voroseal {
namespace {

using nlohmann::json;

// A study outcome made by hand: two runs of one model, one failed with an awkward message.
StudyOutcome sample_outcome() {
  StudyOutcome outcome;
  outcome.study.name = "a<b>";
  outcome.study.output = "/tmp/x";
  outcome.study.steps = {
      {"remesh", json::object()}, {"stats", json::object()}, {"remesh", json::object()}};
  for (int i = 0; i < 2; ++i) {
    RunOutcome r;
    r.run.index = i;
    r.run.model_label = "m<1>";
    r.run.key = i == 0 ? "edge-length=400" : "edge-length=200";
    r.run.swept = {{"edge-length", i == 0 ? 400 : 200}};
    r.status = i == 0 ? "ok" : "failed";
    r.error = i == 0 ? "" : "remesh: meshing failed: bad \"seed\", too close";
    r.measures = {{"vertices", 10 + i}, {"min_angle_deg", 31.25}, {"hausdorff_pct", nullptr}};
    r.histograms = {{"quality", {{"lo", 0.0}, {"hi", 1.0}, {"counts", {0, 3, 7}}}}};
    r.read_seconds = 0.5;
    r.steps = {{"remesh", "ok", 0, 1.5, ""},
               {"stats", i == 0 ? "ok" : "skipped", 0, 0.25, ""},
               {"remesh", "ok", 0, 2.0, ""}};
    if (i == 0) r.picture = "m<1>/edge-length=400/picture.png";
    outcome.runs.push_back(r);
  }
  outcome.failed = 1;
  return outcome;
}

TEST(StudyReport, ColumnsNameSweptParametersAndNumberRepeatedSteps) {
  const std::vector<std::string> columns = summary_columns(sample_outcome());
  const std::vector<std::string> head(columns.begin(), columns.begin() + 5);
  EXPECT_EQ(head, (std::vector<std::string>{"run", "model", "key", "edge-length", "status"}));
  for (const char* c : {"time_remesh_1_s", "time_stats_s", "time_remesh_2_s", "hausdorff_pct",
                        "tets", "regions_preserved", "features_lost_larger_than_cell", "error"})
    EXPECT_NE(std::find(columns.begin(), columns.end(), c), columns.end()) << c;
  EXPECT_EQ(columns.back(), "error");
}

TEST(StudyReport, CsvQuotesAwkwardCellsAndLeavesUnknownsEmpty) {
  const std::string csv = summary_csv(sample_outcome());
  std::vector<std::string> lines;
  for (size_t at = 0, next; (next = csv.find('\n', at)) != std::string::npos; at = next + 1)
    lines.push_back(csv.substr(at, next - at));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1].rfind("1,m<1>,edge-length=400,400,ok,10,,,,,,31.25,", 0), 0u) << lines[1];
  EXPECT_NE(lines[2].find(",\"remesh: meshing failed: bad \"\"seed\"\", too close\""),
            std::string::npos)
      << lines[2];
  const json rows = summary_rows(sample_outcome());
  EXPECT_TRUE(rows[1]["time_stats_s"].is_null()) << "a skipped step has no time";
  EXPECT_EQ(rows[0]["time_remesh_2_s"], 2.0);
}

TEST(StudyReport, HtmlEscapesNamesAndShowsHistogramsAndPictures) {
  const std::string html = html_report(sample_outcome());
  EXPECT_EQ(html.find("a<b>"), std::string::npos);
  EXPECT_NE(html.find("a&lt;b&gt;"), std::string::npos);
  EXPECT_NE(html.find("m&lt;1&gt;"), std::string::npos);
  EXPECT_NE(html.find("src=\"m%3C1%3E/edge-length=400/picture.png\""), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("bad &quot;seed&quot;, too close"), std::string::npos);
  // One <rect> per histogram bin, with a tooltip.
  size_t rects = 0;
  for (size_t at = html.find("<rect"); at != std::string::npos; at = html.find("<rect", at + 1))
    ++rects;
  EXPECT_EQ(rects, 6u);
  EXPECT_NE(html.find("7 triangles (70.00%)"), std::string::npos);
  const json summary = summary_json(sample_outcome());
  EXPECT_EQ(summary["runs_failed"], 1);
  EXPECT_EQ(summary["runs_ok"], 1);
}

TEST(StudyReport, KeyColumnsComeFirstAndTheRestIsBehindAToggle) {
  StudyOutcome outcome = sample_outcome();
  outcome.runs[0].measures["avg_quality"] = 0.8;
  outcome.runs[0].measures["regions_preserved"] = false;
  outcome.runs[0].cut_picture = "m<1>/edge-length=400/cut.png";
  outcome.runs[0].region_legend = {{{"name", "layer<2>"}, {"colour", "#abcdef"}}};
  const std::string html = html_report(outcome);
  const size_t key = html.find("<table class=\"key\">");
  const size_t all = html.find("<details class=\"all\">");
  ASSERT_NE(key, std::string::npos);
  ASSERT_LT(key, all);
  const std::string key_table = html.substr(key, all - key);
  size_t at = 0;
  for (const char* heading : {">run<", ">model<", ">edge-length<", ">status<", ">regions kept<",
                              ">triangles<", ">tets<", ">mean Q<", ">Hausdorff %<", ">time s<"}) {
    const size_t found = key_table.find(heading, at);
    EXPECT_NE(found, std::string::npos) << heading << " (in this order)";
    at = found == std::string::npos ? at : found;
  }
  EXPECT_EQ(key_table.find(">vertices<"), std::string::npos);
  EXPECT_NE(html.find(">vertices<", all), std::string::npos);
  EXPECT_NE(key_table.find("<b class=\"bad\">no</b>"), std::string::npos);
  EXPECT_NE(html.find("src=\"m%3C1%3E/edge-length=400/cut.png\""), std::string::npos);
  EXPECT_NE(html.find("layer&lt;2&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "the report needs no script";
}

}  // namespace
}  // namespace voroseal
