// What a study writes besides each run's own outputs: the summary table (CSV and JSON, one row
// per run with the seed paper's Table 2 columns and the time of every step), each run's
// run.json, and report.html (the key columns, the rest behind a toggle, charts across runs and
// each run's pictures and histograms, report_charts.h), self-contained except for the pictures
// beside it: no script, no network.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/host/context.h"
#include "framework/host/pipeline.h"

namespace voroseal {

/// The quality columns of the summary, in order (the stats module's report keys).
const std::vector<std::string>& summary_measure_keys();

/// The numbers of a run's summary row and its histograms.
struct RunMeasures {
  /// summary_measure_keys() plus tets and min_dihedral_deg; null when unknown. Taken from
  /// context.report["stats"] when the stats step ran (its numbers are authoritative), otherwise
  /// measured on context.model here (hausdorff_pct then stays null); tets from
  /// report["tetmesh"] or context.volume; regions_preserved, features_lost,
  /// features_lost_larger_than_cell, pockets and pockets_opened from
  /// report["remesh"]["topology"]. "measured_by" says which: "stats" or "pipeline".
  nlohmann::json row = nlohmann::json::object();
  /// {"quality": {"lo", "hi", "counts"}, "min_angle_deg": {...}} over the model's triangles;
  /// "dihedral_deg" over the tets' dihedral angles when the run made a volume mesh.
  nlohmann::json histograms = nlohmann::json::object();
};

/// Measures the final state of a run. \pre context.model is set.
RunMeasures measure_run(const Context& context);

/// A run's run.json: parameters, per-step status and timings, the context report, measures.
nlohmann::json run_json(const RunOutcome& outcome, const Study& study);

/// The summary columns: run, model, key, the swept parameters, status, the measures, the time of
/// each step in seconds (time_<step>_s), error.
std::vector<std::string> summary_columns(const StudyOutcome& outcome);
/// One object per run with the summary columns.
nlohmann::json summary_rows(const StudyOutcome& outcome);
/// The summary as CSV (RFC 4180 quoting) and as JSON ({"study", "columns", "runs", ...}).
std::string summary_csv(const StudyOutcome& outcome);
nlohmann::json summary_json(const StudyOutcome& outcome);
/// The HTML report; image paths are relative to the study's output folder.
std::string html_report(const StudyOutcome& outcome);

/// Writes summary.csv, summary.json and report.html into the study's output folder.
/// \throws OutputError
void write_study_reports(const StudyOutcome& outcome);

}  // namespace voroseal
