#include "framework/geometry/triangle_quality.h"

#include <gtest/gtest.h>

#include <cmath>

namespace voroseal {
namespace {

TEST(TriangleQuality, EquilateralIsOneAndSixtyDegrees) {
  const TriangleQuality q = measure_triangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, std::sqrt(3.0), 0));
  EXPECT_NEAR(q.q, 1.0, 1e-12);
  EXPECT_NEAR(q.min_angle_deg, 60.0, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 60.0, 1e-9);
  EXPECT_NEAR(q.area, std::sqrt(3.0), 1e-12);
}

TEST(TriangleQuality, RightIsoscelesByHand) {
  // Legs 1: S = 1/2, h_max = √2, p = (2 + √2)/2, so Q = 6·(1/2) / (√3·√2·(2 + √2)/2).
  const TriangleQuality q = measure_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  const double expected = 3.0 / (std::sqrt(3.0) * std::sqrt(2.0) * (2.0 + std::sqrt(2.0)) / 2.0);
  EXPECT_NEAR(q.q, expected, 1e-12);
  EXPECT_NEAR(q.q, 0.717438935, 1e-8);
  EXPECT_NEAR(q.min_angle_deg, 45.0, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 90.0, 1e-9);
  EXPECT_NEAR(q.area, 0.5, 1e-15);
  // Invariant under scaling, translation and vertex order.
  const TriangleQuality r =
      measure_triangle(Vec3(5, 5, 5) + 1e3 * Vec3(0, 1, 0), Vec3(5, 5, 5), Vec3(5, 5, 5) + 1e3 * Vec3(1, 0, 0));
  EXPECT_NEAR(r.q, q.q, 1e-12);
  EXPECT_NEAR(r.min_angle_deg, 45.0, 1e-9);
}

TEST(TriangleQuality, DegenerateAndNeedle) {
  const TriangleQuality flat = measure_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0));
  EXPECT_EQ(flat.q, 0.0);
  EXPECT_EQ(flat.area, 0.0);
  EXPECT_NEAR(flat.min_angle_deg, 0.0, 1e-12);
  EXPECT_NEAR(flat.max_angle_deg, 180.0, 1e-9);
  const TriangleQuality point = measure_triangle(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1));
  EXPECT_EQ(point.q, 0.0);
  // A needle of angle 1e-6 rad: atan2 keeps the tiny angle accurate.
  const TriangleQuality needle = measure_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1e-6, 0));
  EXPECT_NEAR(needle.min_angle_deg, 1e-6 * 180.0 / M_PI, 1e-15);
}

TEST(TriangleQuality, SummaryCountsAndExtremes) {
  const std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0}, {0, 2, 0}, {10, 0, 0}};
  // Equilateral, right isosceles with legs 2, and a 10 x 2 right triangle (11.3°).
  const std::vector<Triangle> t{{0, 1, 2}, {0, 1, 3}, {0, 4, 3}};
  const QualitySummary s = summarize_quality(v, t);
  EXPECT_EQ(s.triangles, 3);
  EXPECT_EQ(s.below_threshold, 1);  // only the 10 x 2 right triangle has an angle < 30°
  EXPECT_NEAR(s.pct_below_threshold, 100.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.min_angle_deg, std::atan(0.2) * 180 / M_PI, 1e-9);
  EXPECT_EQ(s.min_angle_triangle, 2);
  EXPECT_EQ(s.min_q_triangle, 2);
  EXPECT_NEAR(s.max_angle_deg, 90.0, 1e-9);
  EXPECT_NEAR(s.area, std::sqrt(3.0) + 2.0 + 10.0, 1e-12);
  double sum_q = 0;
  for (const Triangle& f : t) sum_q += measure_triangle(v[f[0]], v[f[1]], v[f[2]]).q;
  EXPECT_NEAR(s.avg_q, sum_q / 3, 1e-15);
  const double h = std::sqrt(104.0);  // hypotenuse of the 10 x 2 triangle
  EXPECT_NEAR(s.min_q, 6 * 10.0 / (std::sqrt(3.0) * h * (12 + h) / 2), 1e-12);
  const QualitySummary none = summarize_quality(v, {});
  EXPECT_EQ(none.triangles, 0);
  EXPECT_EQ(none.pct_below_threshold, 0.0);
}

}  // namespace
}  // namespace voroseal
