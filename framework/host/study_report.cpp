#include "framework/host/study_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "framework/core/error.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"
#include "framework/host/html_text.h"
#include "framework/host/report_charts.h"
#include "io/atomic_file.h"

namespace voroseal {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string>& summary_measure_keys() {
  static const std::vector<std::string> keys = {
      "vertices",     "triangles",   "surfaces",      "contacts",
      "corners",      "regions",     "min_angle_deg", "pct_triangles_angle_below_30",
      "avg_quality",  "min_quality", "area",          "bbox_diagonal",
      "hausdorff_pct"};
  return keys;
}

namespace {

// A histogram of `values` over [lo, hi] in `bins` equal bins (values outside are clamped).
json histogram(const std::vector<double>& values, double lo, double hi, int bins) {
  std::vector<long> counts(bins, 0);
  for (double v : values) {
    int b = static_cast<int>(std::floor((v - lo) / (hi - lo) * bins));
    counts[std::clamp(b, 0, bins - 1)]++;
  }
  return {{"lo", lo}, {"hi", hi}, {"counts", counts}};
}

// The value of `key` in the stats report: at its top level, or in an "output" object.
const json* stats_value(const json& stats, const std::string& key) {
  if (!stats.is_object()) return nullptr;
  if (stats.contains(key) && (stats[key].is_number() || stats[key].is_null())) return &stats[key];
  for (const char* child : {"output", "model", "result"})
    if (stats.contains(child) && stats[child].is_object() && stats[child].contains(key) &&
        stats[child][key].is_number())
      return &stats[child][key];
  return nullptr;
}

// A number for people: integers as is, others with 4 significant digits.
std::string display(const json& value) {
  if (value.is_null()) return "";
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (value.is_number_float()) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value.get<double>());
    return buffer;
  }
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

// The cell of a CSV file (RFC 4180).
std::string csv_cell(const json& value) {
  std::string text = value.is_null()     ? ""
                     : value.is_string() ? value.get<std::string>()
                                         : value.dump();
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Column names of the step timings: time_<module>_s, numbered when a module appears twice.
std::vector<std::string> step_time_columns(const Study& study) {
  std::map<std::string, int> count, seen;
  for (const StudyStep& s : study.steps) ++count[s.module];
  std::vector<std::string> columns;
  for (const StudyStep& s : study.steps) {
    const int k = ++seen[s.module];
    columns.push_back("time_" + s.module + (count[s.module] > 1 ? "_" + std::to_string(k) : "") +
                      "_s");
  }
  return columns;
}

std::vector<std::string> swept_labels(const StudyOutcome& outcome) {
  std::vector<std::string> labels;
  for (const RunOutcome& r : outcome.runs)
    for (const auto& [label, value] : r.run.swept.items())
      if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  return labels;
}

// The summary columns after the quality ones, taken from the steps' reports: tets,
// min_dihedral_deg, thinnest_wedge_deg (the bound the surfaces set on it) and
// thinnest_border_gap_deg (where a free border leaves a surface) from tetmesh;
// from remesh's topology report, whether the regions and their adjacency were kept, how many
// input features have no counterpart (all / larger than a Voronoi cell), how many pockets are
// left (output regions that are no input region) and how many were opened again.
const std::vector<std::string> kStepColumns = {"tets",
                                               "min_dihedral_deg",
                                               "thinnest_wedge_deg",
                                               "thinnest_border_gap_deg",
                                               "regions_preserved",
                                               "features_lost",
                                               "features_lost_larger_than_cell",
                                               "pockets",
                                               "pockets_opened"};

// Atomic, with a temporary of its own: shards sharing an output folder may write at once.
void write_text_file(const std::string& text, const std::string& path,
                     const std::vector<std::string>& inputs) {
  write_atomically(path, inputs, [&](std::ostream& out) { out << text; });
}

}  // namespace

RunMeasures measure_run(const Context& context) {
  RunMeasures measures;
  json& row = measures.row;
  for (const std::string& key : summary_measure_keys()) row[key] = nullptr;
  for (const std::string& key : kStepColumns) row[key] = nullptr;
  if (!context.model) return measures;
  const StructuralModel& model = *context.model;

  const ModelTriangles flat = flatten(model);
  const QualitySummary quality = summarize_quality(model.vertices, flat.triangles, 30.0);
  row["vertices"] = static_cast<long>(model.vertices.size());
  row["triangles"] = static_cast<long>(flat.triangles.size());
  row["surfaces"] = static_cast<long>(model.parts.size());
  row["contacts"] = static_cast<long>(model.contacts.size());
  row["corners"] = static_cast<long>(model.corners.size());
  row["regions"] = static_cast<long>(model.regions.size());
  if (quality.triangles > 0) {
    row["min_angle_deg"] = quality.min_angle_deg;
    row["pct_triangles_angle_below_30"] = quality.pct_below_threshold;
    row["avg_quality"] = quality.avg_q;
    row["min_quality"] = quality.min_q;
  }
  row["area"] = quality.area;
  row["bbox_diagonal"] = model.bbox().diagonal();
  row["measured_by"] = "pipeline";

  // The stats module's numbers replace ours where it gave them.
  if (context.report.contains("stats")) {
    const json& stats = context.report["stats"];
    bool any = false;
    for (const std::string& key : summary_measure_keys())
      if (const json* v = stats_value(stats, key)) {
        row[key] = *v;
        any = true;
      }
    if (any) row["measured_by"] = "stats";
  }

  if (context.report.contains("tetmesh") && context.report["tetmesh"].is_object()) {
    const json& t = context.report["tetmesh"];
    if (t.contains("tets")) row["tets"] = t["tets"];
    if (t.contains("min_dihedral_deg")) row["min_dihedral_deg"] = t["min_dihedral_deg"];
    for (const char* key : {"thinnest_wedge_deg", "thinnest_border_gap_deg"})
      if (t.contains(key)) row[key] = t[key];
  }
  if (row["tets"].is_null() && context.volume)
    row["tets"] = static_cast<long>(context.volume->tets.size());
  if (context.report.contains("remesh") && context.report["remesh"].is_object() &&
      context.report["remesh"].contains("topology")) {
    const json& t = context.report["remesh"]["topology"];
    if (t.contains("regions_preserved")) row["regions_preserved"] = t["regions_preserved"];
    if (t.contains("features_lost") && t["features_lost"].is_array())
      row["features_lost"] = static_cast<long>(t["features_lost"].size());
    if (t.contains("features_lost_larger_than_resolution"))
      row["features_lost_larger_than_cell"] = t["features_lost_larger_than_resolution"];
    if (t.contains("regions_gained") && t["regions_gained"].is_array())
      row["pockets"] = static_cast<long>(t["regions_gained"].size());
    if (t.contains("pockets_removed") && t["pockets_removed"].is_array())
      row["pockets_opened"] = static_cast<long>(t["pockets_removed"].size());
  }

  const std::vector<TriangleQuality> all = triangle_qualities(model.vertices, flat.triangles);
  std::vector<double> q(all.size()), angle(all.size());
  for (size_t t = 0; t < all.size(); ++t) q[t] = all[t].q, angle[t] = all[t].min_angle_deg;
  measures.histograms["quality"] = histogram(q, 0.0, 1.0, 20);
  measures.histograms["min_angle_deg"] = histogram(angle, 0.0, 60.0, 12);
  if (context.volume && !context.volume->tets.empty()) {
    const VolumeMesh& volume = *context.volume;
    std::vector<double> dihedral;
    dihedral.reserve(6 * volume.tets.size());
    for (const Tetrahedron& t : volume.tets) {
      const auto angles = dihedral_angles_deg(volume.vertices[t[0]], volume.vertices[t[1]],
                                              volume.vertices[t[2]], volume.vertices[t[3]]);
      dihedral.insert(dihedral.end(), angles.begin(), angles.end());
    }
    measures.histograms["dihedral_deg"] = histogram(dihedral, 0.0, 180.0, 36);
  }
  return measures;
}

json run_json(const RunOutcome& outcome, const Study& study) {
  json steps = json::array();
  for (const StepOutcome& s : outcome.steps) {
    json step = {{"module", s.module},
                 {"status", s.status},
                 {"exit_code", s.exit_code},
                 {"seconds", s.seconds}};
    if (!s.error.empty()) step["error"] = s.error;
    if (!s.text.empty()) step["text"] = s.text;
    steps.push_back(step);
  }
  json document = {
      {"study", study.name},
      {"study_file", study.file.empty() ? std::string() : fs::absolute(study.file).string()},
      {"definition", study_document(study)},
      {"run", outcome.run.index},
      {"model", outcome.run.model},
      {"model_label", outcome.run.model_label},
      {"key", outcome.run.key},
      {"swept", outcome.run.swept},
      {"parameters", outcome.parameters},
      {"status", outcome.status},
      {"exit_code", outcome.exit_code},
      {"error", outcome.error.empty() ? json(nullptr) : json(outcome.error)},
      {"steps", steps},
      {"seconds",
       {{"read", outcome.read_seconds},
        {"write", outcome.write_seconds},
        {"picture", outcome.picture_seconds},
        {"total", outcome.total_seconds}}},
      {"measures", outcome.measures},
      {"histograms", outcome.histograms},
      {"outputs", outcome.outputs},
      {"picture", outcome.picture.empty() ? json(nullptr) : json(outcome.picture)},
      {"legend", outcome.legend},
      {"cut_picture", outcome.cut_picture.empty() ? json(nullptr) : json(outcome.cut_picture)},
      {"region_legend", outcome.region_legend},
      {"report", outcome.report},
  };
  return document;
}

std::vector<std::string> summary_columns(const StudyOutcome& outcome) {
  std::vector<std::string> columns = {"run", "model", "key"};
  for (const std::string& label : swept_labels(outcome)) columns.push_back(label);
  columns.push_back("status");
  for (const std::string& key : summary_measure_keys()) columns.push_back(key);
  for (const std::string& key : kStepColumns) columns.push_back(key);
  columns.push_back("time_read_s");
  for (const std::string& c : step_time_columns(outcome.study)) columns.push_back(c);
  columns.insert(columns.end(), {"time_write_s", "time_picture_s", "time_total_s", "error"});
  return columns;
}

json summary_rows(const StudyOutcome& outcome) {
  const std::vector<std::string> times = step_time_columns(outcome.study);
  json rows = json::array();
  for (const RunOutcome& r : outcome.runs) {
    json row = json::object();
    row["run"] = r.run.index + 1;
    row["model"] = r.run.model_label;
    row["key"] = r.run.key;
    for (const std::string& label : swept_labels(outcome))
      row[label] = r.run.swept.contains(label) ? r.run.swept[label] : json(nullptr);
    row["status"] = r.status;
    for (const std::string& key : summary_measure_keys())
      row[key] = r.measures.contains(key) ? r.measures[key] : json(nullptr);
    for (const std::string& key : kStepColumns)
      row[key] = r.measures.contains(key) ? r.measures[key] : json(nullptr);
    row["time_read_s"] = r.read_seconds;
    for (size_t s = 0; s < times.size(); ++s)
      row[times[s]] = s < r.steps.size() && r.steps[s].status != "skipped"
                          ? json(r.steps[s].seconds)
                          : json(nullptr);
    row["time_write_s"] = r.write_seconds;
    row["time_picture_s"] = r.picture_seconds;
    row["time_total_s"] = r.total_seconds;
    row["error"] = r.error.empty() ? json(nullptr) : json(r.error);
    rows.push_back(row);
  }
  return rows;
}

std::string summary_csv(const StudyOutcome& outcome) {
  const std::vector<std::string> columns = summary_columns(outcome);
  std::ostringstream csv;
  for (size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << csv_cell(columns[c]);
  csv << "\n";
  for (const json& row : summary_rows(outcome)) {
    for (size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << csv_cell(row[columns[c]]);
    csv << "\n";
  }
  return csv.str();
}

json summary_json(const StudyOutcome& outcome) {
  const Study& study = outcome.study;
  return {{"study", study.name},
          {"file", study.file},
          {"output", study.output},
          {"runs_total", outcome.runs.size()},
          {"runs_ok", static_cast<long>(outcome.runs.size()) - outcome.failed - outcome.invalid},
          {"runs_invalid", outcome.invalid},
          {"runs_failed", outcome.failed},
          {"seconds", outcome.seconds},
          {"columns", summary_columns(outcome)},
          {"runs", summary_rows(outcome)}};
}

namespace {

// The columns of the summary a reader looks at first, with their headings; the swept
// parameters follow the model. The whole summary is behind a toggle below them.
struct KeyColumn {
  const char* key;
  const char* heading;
};
const std::vector<KeyColumn> kKeyColumns = {{"status", "status"},
                                            {"regions_preserved", "regions kept"},
                                            {"triangles", "triangles"},
                                            {"tets", "tets"},
                                            {"avg_quality", "mean Q"},
                                            {"pct_triangles_angle_below_30", "% tri. &lt; 30&deg;"},
                                            {"hausdorff_pct", "Hausdorff %"},
                                            {"min_dihedral_deg", "min dihedral &deg;"},
                                            {"time_total_s", "time s"}};

// The measures charted across runs: summary key, title, axis label.
struct ChartedMeasure {
  const char* key;
  const char* title;
  const char* label;
};
const std::vector<ChartedMeasure> kChartedMeasures = {
    {"avg_quality", "Mean triangle quality Q", "mean Q"},
    {"pct_triangles_angle_below_30", "% triangles with an angle < 30°", "% < 30°"},
    {"hausdorff_pct", "Hausdorff distance, % of diagonal", "Hausdorff %"},
    {"min_dihedral_deg", "Smallest tet dihedral angle (°)", "min dihedral"},
    {"time_total_s", "Time of the run (s)", "seconds"}};

// Swept parameters that set the resolution, preferred as the charts' x axis.
const std::vector<std::string> kResolutionParameters = {"edge-length", "seeds"};

// Histograms of each run: key in RunMeasures::histograms and how it is drawn. The smallest
// angle has the seed paper's 30° threshold marked.
struct RunHistogram {
  const char* key;
  HistogramStyle style;
};
const std::vector<RunHistogram>& run_histograms() {
  static const std::vector<RunHistogram> list = {
      {"quality", {"Triangle quality Q", "Q (1 = equilateral)", "#4a7fb5", "triangles", {}}},
      {"min_angle_deg",
       {"Smallest angle of each triangle", "degrees", "#c0803a", "triangles", 30.0}},
      {"dihedral_deg",
       {"Dihedral angles of the tets", "degrees", "#5a9a5a", "dihedral angles", {}}}};
  return list;
}

bool text_column(const std::string& c) {
  return c == "model" || c == "key" || c == "status" || c == "error";
}

// A cell of the key table: booleans as yes / no, the status as a badge.
std::string key_cell(const std::string& column, const json& value) {
  if (column == "status" && value.is_string())
    return "<span class=\"status " + escape_html(value.get<std::string>()) + "\">" +
           escape_html(value.get<std::string>()) + "</span>";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "<b class=\"bad\">no</b>";
  return escape_html(display(value));
}

// The charts' x axis: a swept resolution parameter, else the first numeric swept parameter,
// else the number of triangles. Returns the summary column and its label.
std::string chart_x_column(const StudyOutcome& outcome, const json& rows) {
  const std::vector<std::string> labels = swept_labels(outcome);
  auto numeric = [&](const std::string& label) {
    for (const json& row : rows)
      if (!row[label].is_number()) return false;
    return !rows.empty();
  };
  for (const std::string& wanted : kResolutionParameters)
    for (const std::string& label : labels) {
      const size_t dot = label.rfind('.');
      const std::string name = dot == std::string::npos ? label : label.substr(dot + 1);
      if (name == wanted && numeric(label)) return label;
    }
  for (const std::string& label : labels)
    if (numeric(label)) return label;
  return "triangles";
}

// The charts across runs, one line per model; "" when there is nothing to chart.
std::string charts_across_runs(const StudyOutcome& outcome, const json& rows) {
  const std::string x = chart_x_column(outcome, rows);
  std::vector<std::string> models;
  for (const json& row : rows) {
    const std::string m = row["model"].get<std::string>();
    if (std::find(models.begin(), models.end(), m) == models.end()) models.push_back(m);
  }
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  for (const json& row : rows)
    if (row[x].is_number()) {
      x_lo = std::min(x_lo, row[x].get<double>());
      x_hi = std::max(x_hi, row[x].get<double>());
    }
  std::ostringstream html;
  for (const ChartedMeasure& measure : kChartedMeasures) {
    std::vector<Series> series;
    for (size_t m = 0; m < models.size(); ++m) {
      Series s{models[m], series_colour(static_cast<int>(m)), {}};
      for (const json& row : rows)
        // A failed run's numbers are those of a half-finished model: left out.
        if (row["model"] == models[m] && row["status"] != "failed" && row[x].is_number() &&
            row[measure.key].is_number())
          s.points.push_back({row[x].get<double>(), row[measure.key].get<double>()});
      series.push_back(s);
    }
    html << line_chart_svg(series, {measure.title, x, measure.label, wants_log_axis(x_lo, x_hi)});
  }
  if (html.str().empty()) return "";
  std::ostringstream out;
  out << "<div class=\"charts\">\n" << html.str() << "\n</div>\n<p class=\"meta\">";
  for (size_t m = 0; m < models.size(); ++m)
    out << "<span class=\"swatch\" style=\"background:" << series_colour(static_cast<int>(m))
        << "\"></span>" << escape_html(models[m]) << " &nbsp; ";
  out << "One point per run (failed runs left out), against " << escape_html(x) << ".</p>\n";
  return out.str();
}

const char* kStyle =
    "body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;margin:20px 24px;color:#222;"
    "background:#fff}\n"
    "h1{font-size:22px;margin:0 0 4px} h2{font-size:18px;margin:22px 0 8px}"
    " h3{font-size:15px;margin:0 0 8px}\n"
    ".meta{color:#555;font-size:13px;margin:4px 0}\n"
    ".table-wrap{overflow-x:auto;border:1px solid #ddd}\n"
    "table{border-collapse:collapse;font-size:12px;white-space:nowrap}\n"
    "table.key{font-size:13px}\n"
    "th,td{padding:3px 7px;border-bottom:1px solid #e4e4e4;text-align:right}\n"
    "th{background:#f3f3ef;position:sticky;top:0} td.text,th.text{text-align:left}\n"
    "tr.failed td{background:#fde8e8} tr.invalid td{background:#fff6dc} b.bad{color:#c53030}\n"
    "details.all{margin:8px 0} details.all>summary{cursor:pointer;color:#355;font-size:13px}\n"
    ".status{display:inline-block;padding:1px 7px;border-radius:9px;font-size:12px;color:#fff}\n"
    ".status.ok{background:#3a7d44} .status.invalid{background:#b7791f}"
    " .status.failed{background:#c53030}\n"
    ".charts{display:flex;flex-wrap:wrap;gap:10px}\n"
    ".run{border:1px solid #ddd;border-radius:6px;padding:12px;margin:14px 0}\n"
    ".run .cols{display:flex;flex-wrap:wrap;gap:14px;align-items:flex-start}\n"
    ".run figure{margin:0;flex:0 1 440px;max-width:440px}\n"
    ".run figcaption{font-size:12px;color:#555}\n"
    ".run img{width:100%;height:auto;border:1px solid #e4e4e4}\n"
    ".histograms{display:flex;flex-wrap:wrap;gap:10px;margin-top:8px}\n"
    "svg text{font-size:10px;fill:#444} svg .title{font-size:12px;fill:#222}\n"
    "svg .axis{stroke:#888;stroke-width:1} svg .grid{stroke:#e6e6e6;stroke-width:1}\n"
    "svg .marker{stroke:#c53030;stroke-width:1;stroke-dasharray:4 3}\n"
    "svg polyline{stroke-width:1.5}\n"
    ".swatch{display:inline-block;width:11px;height:11px;border:1px solid #999;margin-right:4px;"
    "vertical-align:middle}\n"
    ".legend{columns:3;font-size:12px} .regions{font-size:12px;margin-top:4px}\n"
    ".error{color:#c53030;font-family:monospace;white-space:pre-wrap}\n";

// The names and colours of a legend, each in an element `tag` (span or div).
std::string swatch_list(const json& legend, const std::string& tag = "span") {
  std::string out;
  for (const json& entry : legend)
    out += "<" + tag + "><span class=\"swatch\" style=\"background:" +
           escape_html(entry.value("colour", std::string())) + "\"></span>" +
           escape_html(entry.value("name", std::string())) + "</" + tag + "> ";
  return out;
}

}  // namespace

std::string html_report(const StudyOutcome& outcome) {
  const Study& study = outcome.study;
  const std::vector<std::string> columns = summary_columns(outcome);
  const json rows = summary_rows(outcome);
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<title>voroseal study " << escape_html(study.name) << "</title>\n"
       << "<style>\n"
       << kStyle << "</style>\n</head>\n<body>\n";
  html << "<h1>Study " << escape_html(study.name) << "</h1>\n<p class=\"meta\">"
       << outcome.runs.size() << " runs: " << outcome.runs.size() - outcome.failed - outcome.invalid
       << " ok, " << outcome.invalid << " invalid, " << outcome.failed << " failed; "
       << display(json(outcome.seconds)) << " s. Steps: read";
  for (const StudyStep& s : study.steps) html << " &rarr; " << escape_html(s.module);
  if (!study.write.empty()) html << " &rarr; write";
  html << ". Table: <a href=\"summary.csv\">summary.csv</a>, <a href=\"summary.json\">"
          "summary.json</a>.</p>\n";

  // The key columns; the swept parameters are the resolution of each run.
  html << "<h2>Summary</h2>\n<table class=\"key\">\n<thead><tr><th>run</th>"
          "<th class=\"text\">model</th>";
  const std::vector<std::string> swept = swept_labels(outcome);
  for (const std::string& label : swept) html << "<th>" << escape_html(label) << "</th>";
  for (const KeyColumn& c : kKeyColumns)
    html << "<th" << (text_column(c.key) ? " class=\"text\"" : "") << ">" << c.heading << "</th>";
  html << "</tr></thead>\n<tbody>\n";
  for (const json& row : rows) {
    html << "<tr class=\"" << escape_html(row["status"].get<std::string>())
         << "\"><td><a href=\"#run-" << row["run"].dump() << "\">" << row["run"].dump()
         << "</a></td><td class=\"text\">" << escape_html(row["model"].get<std::string>())
         << "</td>";
    for (const std::string& label : swept)
      html << "<td>" << escape_html(display(row[label])) << "</td>";
    for (const KeyColumn& c : kKeyColumns)
      html << "<td" << (text_column(c.key) ? " class=\"text\"" : "") << ">"
           << key_cell(c.key, row[c.key]) << "</td>";
    html << "</tr>\n";
  }
  html << "</tbody></table>\n";

  // Every column, behind a toggle.
  html << "<details class=\"all\"><summary>All " << columns.size()
       << " columns (as in summary.csv)</summary>\n<div class=\"table-wrap\"><table>\n<thead><tr>";
  for (const std::string& c : columns)
    html << "<th" << (text_column(c) ? " class=\"text\"" : "") << ">" << escape_html(c) << "</th>";
  html << "</tr></thead>\n<tbody>\n";
  for (const json& row : rows) {
    html << "<tr class=\"" << escape_html(row["status"].get<std::string>()) << "\">";
    for (const std::string& c : columns) {
      html << "<td" << (text_column(c) ? " class=\"text\"" : "") << ">";
      if (c == "run")
        html << "<a href=\"#run-" << row["run"].dump() << "\">" << row["run"].dump() << "</a>";
      else
        html << escape_html(display(row[c]));
      html << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody></table></div>\n</details>\n";

  const std::string charts = charts_across_runs(outcome, rows);
  if (!charts.empty()) html << "<h2>Across runs</h2>\n" << charts;

  html << "<h2>Runs</h2>\n";
  for (const RunOutcome& r : outcome.runs) {
    const int number = r.run.index + 1;
    html << "<section class=\"run\" id=\"run-" << number << "\">\n<h3>" << number << ". "
         << escape_html(r.run.model_label) << " &mdash; " << escape_html(r.run.key)
         << " <span class=\"status " << escape_html(r.status) << "\">" << escape_html(r.status)
         << "</span></h3>\n";
    if (!r.error.empty()) html << "<p class=\"error\">" << escape_html(r.error) << "</p>\n";
    html << "<div class=\"cols\">\n";
    const std::string what = escape_html(r.run.model_label + " " + r.run.key);
    if (!r.picture.empty())
      html << "<figure><a href=\"" << escape_url(r.picture) << "\"><img src=\""
           << escape_url(r.picture) << "\" width=\"" << study.picture.width << "\" height=\""
           << study.picture.height << "\" alt=\"surfaces of " << what
           << "\"></a><figcaption>Surfaces, one colour per surface part</figcaption></figure>\n";
    if (!r.cut_picture.empty())
      html << "<figure class=\"tets\"><a href=\"" << escape_url(r.cut_picture) << "\"><img src=\""
           << escape_url(r.cut_picture) << "\" width=\"" << study.picture.width << "\" height=\""
           << study.picture.height << "\" alt=\"tet mesh of " << what
           << " cut through its centre\"></a><figcaption>Tet mesh cut through its centre, by "
              "region<div class=\"regions\">"
           << swatch_list(r.region_legend) << "</div></figcaption></figure>\n";
    html << "<div>\n<table>\n<thead><tr><th class=\"text\">step</th><th class=\"text\">status</th>"
            "<th>seconds</th></tr></thead>\n<tbody>\n";
    html << "<tr><td class=\"text\">read</td><td class=\"text\"></td><td>"
         << display(json(r.read_seconds)) << "</td></tr>\n";
    for (const StepOutcome& s : r.steps)
      html << "<tr><td class=\"text\">"
           << (s.text.empty()
                   ? escape_html(s.module)
                   : "<a href=\"" + escape_url(s.text) + "\">" + escape_html(s.module) + "</a>")
           << "</td><td class=\"text\">" << escape_html(s.status) << "</td><td>"
           << (s.status == "skipped" ? "" : display(json(s.seconds))) << "</td></tr>\n";
    html << "<tr><td class=\"text\">write</td><td class=\"text\"></td><td>"
         << display(json(r.write_seconds))
         << "</td></tr>\n<tr><td class=\"text\">total</td><td class=\"text\"></td><td>"
         << display(json(r.total_seconds)) << "</td></tr>\n</tbody></table>\n<p class=\"meta\">";
    // The run's folder: in the study's output, or in a shard's when merged (study_results.h).
    const std::string folder =
        r.run.directory.empty()
            ? (fs::path(r.run.model_label) / r.run.key).generic_string()
            : fs::path(r.run.directory).lexically_relative(study.output).generic_string();
    html << "<a href=\"" << escape_url(folder + "/run.json") << "\">run.json</a>";
    for (const std::string& o : r.outputs)
      html << " &middot; <a href=\"" << escape_url(o) << "\">"
           << escape_html(fs::path(o).filename().string()) << "</a>";
    html << "</p>\n</div>\n</div>\n<div class=\"histograms\">\n";
    for (const RunHistogram& h : run_histograms())
      if (r.histograms.contains(h.key))
        if (const std::optional<Histogram> histogram = histogram_from_json(r.histograms[h.key]))
          html << histogram_svg(*histogram, h.style) << "\n";
    html << "</div>\n";
    if (!r.legend.empty())
      html << "<details><summary>Colours (" << r.legend.size()
           << " surfaces)</summary><div class=\"legend\">\n"
           << swatch_list(r.legend, "div") << "</div></details>\n";
    html << "</section>\n";
  }
  html << "</body>\n</html>\n";
  return html.str();
}

void write_study_reports(const StudyOutcome& outcome) {
  const fs::path folder = outcome.study.output;
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw OutputError(folder.string() + ": " + error.message());
  const std::vector<std::string>& inputs = outcome.study.models;
  write_text_file(summary_csv(outcome), (folder / "summary.csv").string(), inputs);
  write_text_file(summary_json(outcome).dump(2) + "\n", (folder / "summary.json").string(), inputs);
  write_text_file(html_report(outcome), (folder / "report.html").string(), inputs);
}

}  // namespace voroseal
