#include "framework/host/report_charts.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/framework/host/svg_check.h"

namespace voroseal {
namespace {

using test::attribute_values;
using test::count_of;
using test::markup_problem;

std::vector<double> numbers(const std::vector<std::string>& texts) {
  std::vector<double> out;
  for (const std::string& t : texts) out.push_back(std::stod(t));
  return out;
}

TEST(ReportCharts, LogCountScaleShowsASingleElementBesideThousands) {
  EXPECT_EQ(log_count_fraction(0, 10000), 0.0);
  EXPECT_DOUBLE_EQ(log_count_fraction(10000, 10000), 1.0);
  // One bad triangle among 10,000 is 7.5% of the height; on a linear scale it would be 0.01%.
  EXPECT_GT(log_count_fraction(1, 10000), 0.07);
  for (long c = 1; c < 10000; c *= 3)
    EXPECT_LT(log_count_fraction(c, 10000), log_count_fraction(c + 1, 10000)) << c;
}

TEST(ReportCharts, HistogramBarsFollowTheLogScaleAndTheSvgIsWellFormed) {
  Histogram h;
  h.lo = 0, h.hi = 60;
  h.counts = {1, 0, 10, 100, 10000, 3};
  HistogramStyle style;
  style.title = "Smallest angle <of> each triangle";
  style.x_label = "degrees";
  style.marker = 30.0;
  const std::string svg = histogram_svg(h, style);
  EXPECT_EQ(markup_problem(svg), "") << svg;
  EXPECT_NE(svg.find("&lt;of&gt;"), std::string::npos);
  const std::vector<double> heights = numbers(attribute_values(svg, "rect", "height"));
  ASSERT_EQ(heights.size(), h.counts.size());
  const double full = heights[4];
  EXPECT_GT(full, 50);
  EXPECT_EQ(heights[1], 0);
  EXPECT_NEAR(heights[0] / full, log_count_fraction(1, 10000), 0.01);
  EXPECT_NEAR(heights[3] / full, std::log10(101.0) / std::log10(10001.0), 0.01);
  // Bars stand on one base line.
  const std::vector<double> ys = numbers(attribute_values(svg, "rect", "y"));
  for (size_t b = 0; b < ys.size(); ++b) EXPECT_NEAR(ys[b] + heights[b], ys[4] + full, 0.11) << b;
  // Decades labelled up to the peak, the marker drawn, a tooltip per bar.
  for (const char* tick : {">1<", ">10<", ">100<", ">1000<", ">10000<"})
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  EXPECT_EQ(count_of(svg, "class=\"marker\""), 1u);
  EXPECT_NE(svg.find("[0, 10): 1 triangles (0.01%)"), std::string::npos);
}

TEST(ReportCharts, LinearAxesHaveRoundEndsAndEvenSteps) {
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0.61, 0.83}, {0, 1}, {12.5, 12.5}, {-3, 7}, {1e-4, 3e-4}, {3.2, 1187}}) {
    const ChartAxis axis = nice_axis(lo, hi, false);
    EXPECT_LE(axis.lo, lo);
    EXPECT_GE(axis.hi, hi);
    ASSERT_GE(axis.ticks.size(), 3u) << lo;
    EXPECT_LE(axis.ticks.size(), 7u) << lo;
    EXPECT_DOUBLE_EQ(axis.ticks.front(), axis.lo);
    EXPECT_NEAR(axis.ticks.back(), axis.hi, 1e-9 * std::abs(axis.hi));
    const double step = axis.ticks[1] - axis.ticks[0];
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
                std::abs(mantissa - 5) < 1e-6)
        << step;
    if (lo == hi) continue;  // widened around its value
    // No more than one step of room on either side.
    EXPECT_LT(lo - axis.lo, step + 1e-12);
    EXPECT_LT(axis.hi - hi, step + 1e-12);
  }
}

TEST(ReportCharts, LogAxesRunOnOneTwoFive) {
  const ChartAxis a = nice_axis(100, 400, true);
  EXPECT_TRUE(a.log);
  EXPECT_EQ(a.ticks, (std::vector<double>{100, 200, 500}));
  const ChartAxis b = nice_axis(1500, 180000, true);
  EXPECT_DOUBLE_EQ(b.lo, 1000);
  EXPECT_DOUBLE_EQ(b.hi, 200000);
  EXPECT_FALSE(nice_axis(0, 10, true).log) << "zero has no place on a log axis";
  EXPECT_TRUE(wants_log_axis(100, 400));
  EXPECT_FALSE(wants_log_axis(100, 200));
  EXPECT_FALSE(wants_log_axis(0, 1000));
}

TEST(ReportCharts, LineChartPlacesEveryPointInsideItsAxes) {
  EXPECT_EQ(line_chart_svg({{"m", "#000", {}}}, {"t", "x", "y", false}), "");
  const std::vector<Series> series = {
      {"folded", series_colour(0), {{400, 0.71}, {100, 0.83}, {200, 0.79}}},
      {"faulted & co", series_colour(1), {{400, 0.65}, {200, 0.74}, {100, NAN}}}};
  const std::string svg = line_chart_svg(series, {"Mean Q", "edge-length", "mean Q", true});
  EXPECT_EQ(markup_problem(svg), "") << svg;
  EXPECT_EQ(count_of(svg, "<circle"), 5u) << "a point without a value is left out";
  EXPECT_EQ(count_of(svg, "<polyline"), 2u);
  EXPECT_NE(svg.find("edge-length (log)"), std::string::npos);
  EXPECT_NE(svg.find("faulted &amp; co"), std::string::npos);
  const std::vector<double> xs = numbers(attribute_values(svg, "circle", "cx"));
  const std::vector<double> ys = numbers(attribute_values(svg, "circle", "cy"));
  const double width = std::stod(attribute_values(svg, "svg", "width")[0]);
  const double height = std::stod(attribute_values(svg, "svg", "height")[0]);
  for (size_t i = 0; i < xs.size(); ++i) {
    EXPECT_GT(xs[i], 0);
    EXPECT_LT(xs[i], width);
    EXPECT_GT(ys[i], 0);
    EXPECT_LT(ys[i], height);
  }
  // The first series, sorted by x: 100, 200, 400 left to right; quality falls as x grows.
  EXPECT_LT(xs[0], xs[1]);
  EXPECT_LT(xs[1], xs[2]);
  EXPECT_LT(ys[0], ys[2]) << "higher values are drawn higher";
  // On a log axis 200 is halfway between 100 and 400.
  EXPECT_NEAR(xs[1] - xs[0], xs[2] - xs[1], 0.2);
}

TEST(ReportCharts, HistogramsAreReadBackFromRunJsonOrRefused) {
  const auto h = histogram_from_json({{"lo", 0}, {"hi", 1}, {"counts", {1, 2, 3}}});
  ASSERT_TRUE(h.has_value());
  EXPECT_EQ(h->counts, (std::vector<long>{1, 2, 3}));
  EXPECT_FALSE(histogram_from_json(nlohmann::json::object()).has_value());
  EXPECT_FALSE(histogram_from_json({{"lo", 1}, {"hi", 1}, {"counts", {1}}}).has_value());
  EXPECT_FALSE(histogram_from_json({{"lo", 0}, {"hi", 1}, {"counts", {"a"}}}).has_value());
}

}  // namespace
}  // namespace voroseal
