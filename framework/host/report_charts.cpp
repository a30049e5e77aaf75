#include "framework/host/report_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "framework/host/html_text.h"

namespace voroseal {

namespace {

// Values spanning at least this ratio go on a log axis (a resolution halved twice does).
constexpr double kLogAxisRatio = 3.0;

// Chart sizes in CSS pixels: five line charts side by side fit in a 1,400 px window.
constexpr int kHistogramWidth = 320, kHistogramHeight = 170;
constexpr int kChartWidth = 250, kChartHeight = 190;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// A coordinate in an SVG attribute.
std::string px(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

// Maps a value on an axis to [0, 1].
double fraction(const ChartAxis& axis, double value) {
  if (axis.log) {
    const double lo = std::log10(axis.lo), hi = std::log10(axis.hi);
    return hi > lo ? (std::log10(std::max(value, axis.lo * 1e-9)) - lo) / (hi - lo) : 0.5;
  }
  return axis.hi > axis.lo ? (value - axis.lo) / (axis.hi - axis.lo) : 0.5;
}

std::string svg_open(const char* css_class, int width, int height, const std::string& title) {
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"" << css_class << "\" width=\"" << width
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" role=\"img\" aria-label=\"" << escape_html(title) << "\">\n";
  return svg.str();
}

std::string text(double x, double y, const std::string& content, const char* anchor,
                 const char* css_class = nullptr) {
  std::string out = "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\" text-anchor=\"" + anchor + "\"";
  if (css_class) out += std::string(" class=\"") + css_class + "\"";
  return out + ">" + escape_html(content) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* css_class) {
  return "<line x1=\"" + px(x1) + "\" y1=\"" + px(y1) + "\" x2=\"" + px(x2) + "\" y2=\"" + px(y2) +
         "\" class=\"" + css_class + "\"/>\n";
}

}  // namespace

std::optional<Histogram> histogram_from_json(const nlohmann::json& value) {
  if (!value.is_object() || !value.contains("counts") || !value["counts"].is_array() ||
      !value.contains("lo") || !value.contains("hi") || !value["lo"].is_number() ||
      !value["hi"].is_number())
    return std::nullopt;
  Histogram h;
  h.lo = value["lo"].get<double>();
  h.hi = value["hi"].get<double>();
  for (const auto& c : value["counts"]) {
    if (!c.is_number()) return std::nullopt;
    h.counts.push_back(c.get<long>());
  }
  if (h.counts.empty() || !(h.hi > h.lo)) return std::nullopt;
  return h;
}

double log_count_fraction(long count, long peak) {
  if (count <= 0 || peak <= 0) return 0.0;
  return std::log10(1.0 + count) / std::log10(1.0 + peak);
}

std::string histogram_svg(const Histogram& h, const HistogramStyle& style) {
  long peak = 0, total = 0;
  for (long c : h.counts) peak = std::max(peak, c), total += c;
  const int width = kHistogramWidth, height = kHistogramHeight;
  const int left = 44, right = 10, top = 22, bottom = 34;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  const double base = top + plot_h;
  const size_t bins = h.counts.size();
  const double bar_w = plot_w / std::max<size_t>(bins, 1);
  std::ostringstream svg;
  svg << svg_open("histogram", width, height, style.title);
  svg << text(left, 14, style.title, "start", "title");
  // Decades of the log count scale as grid lines: 1, 10, 100, ... up to the peak.
  for (long tick = 1; tick <= std::max(peak, 1L); tick *= 10) {
    const double y = base - plot_h * log_count_fraction(tick, std::max(peak, 1L));
    svg << line(left, y, left + plot_w, y, "grid");
    svg << text(left - 4, y + 3.5, std::to_string(tick), "end");
    if (tick > std::numeric_limits<long>::max() / 10) break;
  }
  for (size_t b = 0; b < bins; ++b) {
    const double bar_h = plot_h * log_count_fraction(h.counts[b], peak);
    const double from = h.lo + (h.hi - h.lo) * b / bins, to = h.lo + (h.hi - h.lo) * (b + 1) / bins;
    char tip[128];
    std::snprintf(tip, sizeof tip, "[%.3g, %.3g): %ld %s (%.2f%%)", from, to, h.counts[b],
                  style.items.c_str(), total > 0 ? 100.0 * h.counts[b] / total : 0.0);
    svg << "<rect x=\"" << px(left + b * bar_w + 0.5) << "\" y=\"" << px(base - bar_h)
        << "\" width=\"" << px(std::max(bar_w - 1.0, 0.5)) << "\" height=\"" << px(bar_h)
        << "\" fill=\"" << escape_html(style.colour) << "\"><title>" << escape_html(tip)
        << "</title></rect>\n";
  }
  svg << line(left, base, left + plot_w, base, "axis") << line(left, top, left, base, "axis");
  if (style.marker && *style.marker > h.lo && *style.marker < h.hi) {
    const double x = left + plot_w * (*style.marker - h.lo) / (h.hi - h.lo);
    svg << line(x, top, x, base, "marker");
  }
  const double labels = base + 13;
  svg << text(left, labels, number(h.lo), "middle")
      << text(left + plot_w / 2, labels, number(0.5 * (h.lo + h.hi)), "middle")
      << text(left + plot_w, labels, number(h.hi), "middle")
      << text(left + plot_w / 2, height - 4, style.x_label + " (count on a log scale)", "middle");
  svg << "</svg>";
  return svg.str();
}

bool wants_log_axis(double lo, double hi) {
  return lo > 0 && hi >= kLogAxisRatio * lo;
}

ChartAxis nice_axis(double lo, double hi, bool log) {
  ChartAxis axis;
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (lo > hi) std::swap(lo, hi);
  axis.log = log && lo > 0;
  if (axis.log) {
    // Ends and ticks on the 1-2-5 sequence.
    auto step_value = [](int k) {  // k = 3 * decade + (0, 1, 2 for 1, 2, 5)
      const int decade = static_cast<int>(std::floor(k / 3.0)), m = k - 3 * decade;
      return std::pow(10.0, decade) * (m == 0 ? 1.0 : m == 1 ? 2.0 : 5.0);
    };
    int k = static_cast<int>(std::floor(std::log10(lo))) * 3;
    while (step_value(k + 1) <= lo * (1 + 1e-12)) ++k;
    while (step_value(k) > lo * (1 + 1e-12)) --k;
    for (; step_value(k) < hi * (1 - 1e-12); ++k) axis.ticks.push_back(step_value(k));
    axis.ticks.push_back(step_value(k));
    if (axis.ticks.size() == 1) axis.ticks.push_back(step_value(k + 1));
    axis.lo = axis.ticks.front();
    axis.hi = axis.ticks.back();
    return axis;
  }
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double pad = lo == 0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad, hi += pad;
  }
  const double rough = (hi - lo) / 4;
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  double step = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= rough * (1 - 1e-9)) {
      step = m * decade;
      break;
    }
  axis.lo = std::floor(lo / step + 1e-9) * step;
  axis.hi = std::ceil(hi / step - 1e-9) * step;
  for (double t = axis.lo; t <= axis.hi + 0.5 * step; t += step)
    axis.ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
  return axis;
}

std::string series_colour(int index) {
  static const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                        "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
  return colours[static_cast<size_t>(std::max(index, 0)) % (sizeof colours / sizeof *colours)];
}

std::string line_chart_svg(const std::vector<Series>& series, const LineChartStyle& style) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Series& s : series)
    for (const auto& p : s.points) {
      if (!std::isfinite(p[0]) || !std::isfinite(p[1])) continue;
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
  if (!(x0 <= x1)) return "";
  const ChartAxis xa = nice_axis(x0, x1, style.log_x && x0 > 0);
  const ChartAxis ya = nice_axis(y0, y1, false);
  const int width = kChartWidth, height = kChartHeight;
  const int left = 46, right = 12, top = 22, bottom = 36;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  const double base = top + plot_h;
  auto sx = [&](double x) { return left + plot_w * fraction(xa, x); };
  auto sy = [&](double y) { return base - plot_h * fraction(ya, y); };

  std::ostringstream svg;
  svg << svg_open("chart", width, height, style.title);
  svg << text(left - 40, 14, style.title, "start", "title");
  for (double t : ya.ticks)
    svg << line(left, sy(t), left + plot_w, sy(t), "grid")
        << text(left - 4, sy(t) + 3.5, number(t), "end");
  for (double t : xa.ticks)
    svg << line(sx(t), base, sx(t), base + 3, "axis")
        << text(sx(t), base + 13, number(t), "middle");
  svg << line(left, base, left + plot_w, base, "axis") << line(left, top, left, base, "axis");
  svg << text(left + plot_w / 2, height - 5, style.x_label + (xa.log ? " (log)" : ""), "middle");
  for (const Series& s : series) {
    std::vector<std::array<double, 2>> points;
    for (const auto& p : s.points)
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && (!xa.log || p[0] > 0)) points.push_back(p);
    std::sort(points.begin(), points.end());
    if (points.size() > 1) {
      svg << "<polyline fill=\"none\" stroke=\"" << escape_html(s.colour) << "\" points=\"";
      for (size_t i = 0; i < points.size(); ++i)
        svg << (i ? " " : "") << px(sx(points[i][0])) << ',' << px(sy(points[i][1]));
      svg << "\"/>\n";
    }
    for (const auto& p : points)
      svg << "<circle cx=\"" << px(sx(p[0])) << "\" cy=\"" << px(sy(p[1])) << "\" r=\"3.5\" fill=\""
          << escape_html(s.colour) << "\"><title>"
          << escape_html(s.name + ": " + style.x_label + " " + number(p[0]) + ", " + style.y_label +
                         " " + number(p[1]))
          << "</title></circle>\n";
  }
  svg << "</svg>";
  return svg.str();
}

}  // namespace voroseal
