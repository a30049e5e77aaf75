// Shape quality of triangles (seed paper, Table 2; design.md "Metrics"): angles and
// Q = 6S / (√3 · h_max · p), S the area, h_max the longest edge, p the half-perimeter; Q = 1 for
// an equilateral triangle, 0 for a degenerate one. Same formulas as the referee meshreport
// (quality.h), so the numbers agree.
#pragma once

#include <vector>

#include "framework/core/types.h"

namespace voroseal {

struct TriangleQuality {
  double min_angle_deg = 0;  // 0 for a degenerate triangle
  double max_angle_deg = 0;
  double q = 0;  // 6S / (√3 · h_max · p), 0 when h_max = 0
  double area = 0;
};

/// Angles from atan2(|u × v|, u · v), robust for needles.
TriangleQuality measure_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

/// The smallest angle alone (the one facing the shortest edge), as measure_triangle() gives it.
double min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c);

/// Aggregates over a set of triangles.
struct QualitySummary {
  long triangles = 0;
  double min_angle_deg = 0;  // smallest angle of any triangle (0 when there is none)
  double max_angle_deg = 0;
  double mean_min_angle_deg = 0;   // mean over triangles of their smallest angle
  long below_threshold = 0;        // triangles with an angle < angle_threshold_deg
  double pct_below_threshold = 0;  // in % of the triangles
  double avg_q = 0, min_q = 0;
  double area = 0;
  int min_angle_triangle = -1;  // index of the triangle with the smallest angle
  int min_q_triangle = -1;
};

/// Quality of every triangle, in parallel. Indices must be valid (not checked).
std::vector<TriangleQuality> triangle_qualities(const std::vector<Vec3>& vertices,
                                                const std::vector<Triangle>& triangles);

/// Summary over all triangles; angles below `angle_threshold_deg` (30° in the seed paper) count
/// as bad.
QualitySummary summarize_quality(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                 double angle_threshold_deg = 30.0);

}  // namespace voroseal
