#include "framework/host/study_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "framework/core/error.h"
#include "framework/geometry/triangle_quality.h"
#include "io/atomic_file.h"

namespace voroseal {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string>& summary_measure_keys() {
  static const std::vector<std::string> keys = {
      "vertices",    "triangles",  "surfaces",     "contacts",
      "corners",     "regions",    "min_angle_deg", "pct_triangles_angle_below_30",
      "avg_quality", "min_quality", "area",         "bbox_diagonal",
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

std::string escape_html(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

// Percent-encodes what is not safe in a relative URL path (keeps '/').
std::string escape_url(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '=' || c == '~') {
      out += static_cast<char>(c);
    } else {
      char buffer[4];
      std::snprintf(buffer, sizeof buffer, "%%%02X", c);
      out += buffer;
    }
  }
  return out;
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
  std::string text = value.is_null() ? "" : value.is_string() ? value.get<std::string>() : value.dump();
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
    columns.push_back("time_" + s.module + (count[s.module] > 1 ? "_" + std::to_string(k) : "") + "_s");
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
// min_dihedral_deg and thinnest_wedge_deg (the bound the surfaces set on it) from tetmesh;
// from remesh's topology report, whether the regions and their adjacency were kept, how many
// input features have no counterpart (all / larger than a Voronoi cell), how many pockets are
// left (output regions that are no input region) and how many were opened again.
const std::vector<std::string> kStepColumns = {
    "tets", "min_dihedral_deg", "thinnest_wedge_deg", "regions_preserved", "features_lost",
    "features_lost_larger_than_cell", "pockets", "pockets_opened"};

// An inline SVG bar chart of a histogram.
std::string svg_histogram(const std::string& title, const json& h, const std::string& colour,
                          const std::string& x_label) {
  if (!h.is_object() || !h.contains("counts")) return "";
  const std::vector<long> counts = h["counts"].get<std::vector<long>>();
  const double lo = h["lo"].get<double>(), hi = h["hi"].get<double>();
  long peak = 1, total = 0;
  for (long c : counts) peak = std::max(peak, c), total += c;
  const int width = 320, height = 170, left = 44, right = 10, top = 22, bottom = 34;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  const double bar_w = plot_w / std::max<size_t>(counts.size(), 1);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"histogram\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" role=\"img\" aria-label=\"" << escape_html(title)
      << "\">\n";
  svg << "<text x=\"" << left << "\" y=\"14\" class=\"title\">" << escape_html(title) << "</text>\n";
  svg << "<line x1=\"" << left << "\" y1=\"" << top + plot_h << "\" x2=\"" << left + plot_w << "\" y2=\""
      << top + plot_h << "\" class=\"axis\"/>\n";
  svg << "<line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\"" << top + plot_h
      << "\" class=\"axis\"/>\n";
  for (size_t b = 0; b < counts.size(); ++b) {
    const double bar_h = plot_h * counts[b] / peak;
    const double x = left + b * bar_w, y = top + plot_h - bar_h;
    const double from = lo + (hi - lo) * b / counts.size(), to = lo + (hi - lo) * (b + 1) / counts.size();
    char tip[96];
    std::snprintf(tip, sizeof tip, "[%.3g, %.3g): %ld triangles (%.1f%%)", from, to, counts[b],
                  total > 0 ? 100.0 * counts[b] / total : 0.0);
    svg << "<rect x=\"" << x + 0.5 << "\" y=\"" << y << "\" width=\"" << std::max(bar_w - 1.0, 0.5)
        << "\" height=\"" << bar_h << "\" fill=\"" << colour << "\"><title>" << tip << "</title></rect>\n";
  }
  char lo_text[32], mid_text[32], hi_text[32];
  std::snprintf(lo_text, sizeof lo_text, "%g", lo);
  std::snprintf(mid_text, sizeof mid_text, "%g", 0.5 * (lo + hi));
  std::snprintf(hi_text, sizeof hi_text, "%g", hi);
  const double base = top + plot_h + 13;
  svg << "<text x=\"" << left << "\" y=\"" << base << "\" text-anchor=\"middle\">" << lo_text << "</text>\n";
  svg << "<text x=\"" << left + plot_w / 2 << "\" y=\"" << base << "\" text-anchor=\"middle\">" << mid_text
      << "</text>\n";
  svg << "<text x=\"" << left + plot_w << "\" y=\"" << base << "\" text-anchor=\"middle\">" << hi_text
      << "</text>\n";
  svg << "<text x=\"" << left + plot_w / 2 << "\" y=\"" << height - 4 << "\" text-anchor=\"middle\">"
      << escape_html(x_label) << "</text>\n";
  svg << "<text x=\"" << left - 4 << "\" y=\"" << top + 4 << "\" text-anchor=\"end\">" << peak << "</text>\n";
  svg << "<text x=\"" << left - 4 << "\" y=\"" << top + plot_h << "\" text-anchor=\"end\">0</text>\n";
  svg << "</svg>";
  return svg.str();
}

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
    if (t.contains("thinnest_wedge_deg")) row["thinnest_wedge_deg"] = t["thinnest_wedge_deg"];
  }
  if (row["tets"].is_null() && context.volume) row["tets"] = static_cast<long>(context.volume->tets.size());
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
  return measures;
}

json run_json(const RunOutcome& outcome, const Study& study) {
  json steps = json::array();
  for (const StepOutcome& s : outcome.steps) {
    json step = {{"module", s.module}, {"status", s.status}, {"exit_code", s.exit_code}, {"seconds", s.seconds}};
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
      row[times[s]] = s < r.steps.size() && r.steps[s].status != "skipped" ? json(r.steps[s].seconds) : json(nullptr);
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

std::string html_report(const StudyOutcome& outcome) {
  const Study& study = outcome.study;
  const std::vector<std::string> columns = summary_columns(outcome);
  const json rows = summary_rows(outcome);
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<title>voroseal study " << escape_html(study.name) << "</title>\n"
       << "<style>\n"
          "body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;margin:24px;color:#222;background:#fff}\n"
          "h1{font-size:22px;margin:0 0 4px} h2{font-size:18px;margin:28px 0 8px} h3{font-size:15px;margin:0 0 8px}\n"
          ".meta{color:#555;font-size:13px}\n"
          ".table-wrap{overflow-x:auto;border:1px solid #ddd}\n"
          "table{border-collapse:collapse;font-size:12px;white-space:nowrap}\n"
          "th,td{padding:3px 7px;border-bottom:1px solid #e4e4e4;text-align:right}\n"
          "th{background:#f3f3ef;position:sticky;top:0} td.text,th.text{text-align:left}\n"
          "tr.failed td{background:#fde8e8} tr.invalid td{background:#fff6dc}\n"
          ".status{display:inline-block;padding:1px 7px;border-radius:9px;font-size:12px;color:#fff}\n"
          ".status.ok{background:#3a7d44} .status.invalid{background:#b7791f} .status.failed{background:#c53030}\n"
          ".run{border:1px solid #ddd;border-radius:6px;padding:12px;margin:14px 0}\n"
          ".run .cols{display:flex;flex-wrap:wrap;gap:14px;align-items:flex-start}\n"
          ".run .cols>a{flex:0 1 560px;max-width:560px}\n"
          ".run img{width:100%;height:auto;border:1px solid #e4e4e4}\n"
          ".histogram text{font-size:10px;fill:#444} .histogram .title{font-size:12px;fill:#222}\n"
          ".histogram .axis{stroke:#888;stroke-width:1}\n"
          ".swatch{display:inline-block;width:11px;height:11px;border:1px solid #999;margin-right:4px;"
          "vertical-align:middle}\n"
          ".legend{columns:3;font-size:12px} .error{color:#c53030;font-family:monospace;white-space:pre-wrap}\n"
          "</style>\n</head>\n<body>\n";
  html << "<h1>Study " << escape_html(study.name) << "</h1>\n<p class=\"meta\">" << outcome.runs.size() << " runs: "
       << outcome.runs.size() - outcome.failed - outcome.invalid << " ok, " << outcome.invalid << " invalid, "
       << outcome.failed << " failed; " << display(json(outcome.seconds)) << " s. Steps: read";
  for (const StudyStep& s : study.steps) html << " &rarr; " << escape_html(s.module);
  if (!study.write.empty()) html << " &rarr; write";
  html << ". Table: <a href=\"summary.csv\">summary.csv</a>, <a href=\"summary.json\">summary.json</a>.</p>\n";

  html << "<h2>Summary</h2>\n<div class=\"table-wrap\"><table>\n<thead><tr>";
  for (const std::string& c : columns) {
    const bool text = c == "model" || c == "key" || c == "status" || c == "error";
    html << "<th" << (text ? " class=\"text\"" : "") << ">" << escape_html(c) << "</th>";
  }
  html << "</tr></thead>\n<tbody>\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    const json& row = rows[i];
    html << "<tr class=\"" << escape_html(row["status"].get<std::string>()) << "\">";
    for (const std::string& c : columns) {
      const bool text = c == "model" || c == "key" || c == "status" || c == "error";
      html << "<td" << (text ? " class=\"text\"" : "") << ">";
      if (c == "run")
        html << "<a href=\"#run-" << row["run"].dump() << "\">" << row["run"].dump() << "</a>";
      else
        html << escape_html(display(row[c]));
      html << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody></table></div>\n";

  html << "<h2>Runs</h2>\n";
  for (const RunOutcome& r : outcome.runs) {
    const int number = r.run.index + 1;
    html << "<section class=\"run\" id=\"run-" << number << "\">\n<h3>" << number << ". "
         << escape_html(r.run.model_label) << " &mdash; " << escape_html(r.run.key) << " <span class=\"status "
         << escape_html(r.status) << "\">" << escape_html(r.status) << "</span></h3>\n";
    if (!r.error.empty()) html << "<p class=\"error\">" << escape_html(r.error) << "</p>\n";
    html << "<div class=\"cols\">\n";
    if (!r.picture.empty())
      html << "<a href=\"" << escape_url(r.picture) << "\"><img src=\"" << escape_url(r.picture) << "\" width=\""
           << study.picture.width << "\" height=\"" << study.picture.height << "\" alt=\"surfaces of "
           << escape_html(r.run.model_label + " " + r.run.key) << "\"></a>\n";
    html << "<div>\n";
    if (r.histograms.contains("quality"))
      html << svg_histogram("Triangle quality Q", r.histograms["quality"], "#4a7fb5", "Q (1 = equilateral)")
           << "\n";
    if (r.histograms.contains("min_angle_deg"))
      html << svg_histogram("Smallest angle of each triangle", r.histograms["min_angle_deg"], "#c0803a", "degrees")
           << "\n";
    html << "</div>\n<div>\n<table>\n<thead><tr><th class=\"text\">step</th><th class=\"text\">status</th>"
            "<th>seconds</th></tr></thead>\n<tbody>\n";
    html << "<tr><td class=\"text\">read</td><td class=\"text\"></td><td>" << display(json(r.read_seconds))
         << "</td></tr>\n";
    for (const StepOutcome& s : r.steps)
      html << "<tr><td class=\"text\">"
           << (s.text.empty() ? escape_html(s.module)
                              : "<a href=\"" + escape_url(s.text) + "\">" + escape_html(s.module) + "</a>")
           << "</td><td class=\"text\">" << escape_html(s.status)
           << "</td><td>" << (s.status == "skipped" ? "" : display(json(s.seconds))) << "</td></tr>\n";
    html << "<tr><td class=\"text\">write</td><td class=\"text\"></td><td>" << display(json(r.write_seconds))
         << "</td></tr>\n<tr><td class=\"text\">total</td><td class=\"text\"></td><td>"
         << display(json(r.total_seconds)) << "</td></tr>\n</tbody></table>\n<p class=\"meta\">";
    // The run's folder: in the study's output, or in a shard's when merged (study_results.h).
    const std::string folder =
        r.run.directory.empty()
            ? (fs::path(r.run.model_label) / r.run.key).generic_string()
            : fs::path(r.run.directory).lexically_relative(study.output).generic_string();
    html << "<a href=\"" << escape_url(folder + "/run.json") << "\">run.json</a>";
    for (const std::string& o : r.outputs)
      html << " &middot; <a href=\"" << escape_url(o) << "\">" << escape_html(fs::path(o).filename().string())
           << "</a>";
    html << "</p>\n</div>\n</div>\n";
    if (!r.legend.empty()) {
      html << "<details><summary>Colours (" << r.legend.size() << " surfaces)</summary><div class=\"legend\">\n";
      for (const json& entry : r.legend)
        html << "<div><span class=\"swatch\" style=\"background:" << escape_html(entry["colour"].get<std::string>())
             << "\"></span>" << escape_html(entry["name"].get<std::string>()) << "</div>\n";
      html << "</div></details>\n";
    }
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
