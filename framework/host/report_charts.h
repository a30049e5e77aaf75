// Charts of the study report as inline SVG (no script, no network): histograms of element
// quality on a log count scale, so that the few worst elements show beside thousands of good
// ones, and line charts of a measure across the runs of a study.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace voroseal {

/// Counts in equal bins over [lo, hi].
struct Histogram {
  double lo = 0, hi = 1;
  std::vector<long> counts;
};

/// {"lo", "hi", "counts"} as run.json holds it; nullopt when it is not one.
std::optional<Histogram> histogram_from_json(const nlohmann::json& value);

struct HistogramStyle {
  std::string title;
  std::string x_label;
  std::string colour = "#4a7fb5";
  std::string items = "triangles";  // what is counted, in the tooltips
  std::optional<double> marker;     // a dashed line at this value (a threshold)
};

/// A bar's height as a fraction of the plot: log10(1 + count) / log10(1 + peak). 0 for none,
/// the full height for the peak, and a single element a visible bar.
double log_count_fraction(long count, long peak);

std::string histogram_svg(const Histogram& histogram, const HistogramStyle& style);

/// An axis: its ends and the values labelled on it.
struct ChartAxis {
  double lo = 0, hi = 1;
  bool log = false;
  std::vector<double> ticks;  // from lo to hi, lo and hi included
};

/// An axis covering [lo, hi] with round ends. Linear: ticks 1, 2 or 5 times a power of ten
/// apart, four or five of them. Log (lo > 0): ends and ticks at 1, 2 and 5 times powers of ten.
/// An empty range is widened around its value.
ChartAxis nice_axis(double lo, double hi, bool log);

/// Whether values spread over [lo, hi] read better on a log axis: all positive and the
/// largest at least kLogAxisRatio times the smallest.
bool wants_log_axis(double lo, double hi);

/// One line of a chart: (x, y) points, drawn in order of x; `colour` a CSS colour.
struct Series {
  std::string name;
  std::string colour;
  std::vector<std::array<double, 2>> points;
};

struct LineChartStyle {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
};

/// A line chart with points (each with a tooltip), axes and ticks; "" when no series has a
/// point.
std::string line_chart_svg(const std::vector<Series>& series, const LineChartStyle& style);

/// Distinct colours for the series of a chart, one per index.
std::string series_colour(int index);

}  // namespace voroseal
