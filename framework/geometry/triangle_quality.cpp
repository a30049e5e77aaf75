#include "framework/geometry/triangle_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voroseal {

namespace {

// The angle at the vertex facing edge `edge` (edge k joins p[k] and p[k + 1]), in degrees.
double angle_facing(const Vec3* const p[3], int edge, double twice_area) {
  const int k = (edge + 2) % 3;
  const Vec3 u = *p[(k + 1) % 3] - *p[k], v = *p[(k + 2) % 3] - *p[k];
  return std::atan2(twice_area, u.dot(v)) * (180.0 / M_PI);
}

}  // namespace

// The smallest angle faces the shortest edge and the largest the longest (law of sines): two
// angles are measured, not three (this is the remesher's clean-up's innermost measure).
TriangleQuality measure_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* p[3] = {&a, &b, &c};
  double len[3];
  for (int k = 0; k < 3; ++k) len[k] = (*p[(k + 1) % 3] - *p[k]).norm();
  const double twice_area = (b - a).cross(c - a).norm();
  const int shortest = static_cast<int>(std::min_element(len, len + 3) - len);
  const int longest = static_cast<int>(std::max_element(len, len + 3) - len);
  TriangleQuality tq;
  tq.area = 0.5 * twice_area;
  const double h_max = len[longest];
  const double half_perimeter = 0.5 * (len[0] + len[1] + len[2]);
  tq.q = h_max > 0 ? 6.0 * tq.area / (std::sqrt(3.0) * h_max * half_perimeter) : 0.0;
  tq.min_angle_deg = angle_facing(p, shortest, twice_area);
  tq.max_angle_deg = angle_facing(p, longest, twice_area);
  return tq;
}

double min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* p[3] = {&a, &b, &c};
  double len[3];
  for (int k = 0; k < 3; ++k) len[k] = (*p[(k + 1) % 3] - *p[k]).squaredNorm();
  const int shortest = static_cast<int>(std::min_element(len, len + 3) - len);
  return angle_facing(p, shortest, (b - a).cross(c - a).norm());
}

std::vector<TriangleQuality> triangle_qualities(const std::vector<Vec3>& vertices,
                                                const std::vector<Triangle>& triangles) {
  std::vector<TriangleQuality> result(triangles.size());
  const long n = static_cast<long>(triangles.size());
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t) {
    const Triangle& f = triangles[t];
    result[t] = measure_triangle(vertices[f[0]], vertices[f[1]], vertices[f[2]]);
  }
  return result;
}

QualitySummary summarize_quality(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                 double angle_threshold_deg) {
  const std::vector<TriangleQuality> all = triangle_qualities(vertices, triangles);
  QualitySummary s;
  s.triangles = static_cast<long>(all.size());
  if (all.empty()) return s;
  // Sequential sums in triangle order: the same total whatever the thread count.
  double sum_q = 0, sum_min_angle = 0;
  s.min_angle_deg = s.min_q = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < all.size(); ++t) {
    const TriangleQuality& tq = all[t];
    s.area += tq.area;
    sum_q += tq.q;
    sum_min_angle += tq.min_angle_deg;
    if (tq.min_angle_deg < angle_threshold_deg) ++s.below_threshold;
    if (tq.min_angle_deg < s.min_angle_deg) {
      s.min_angle_deg = tq.min_angle_deg;
      s.min_angle_triangle = static_cast<int>(t);
    }
    if (tq.q < s.min_q) {
      s.min_q = tq.q;
      s.min_q_triangle = static_cast<int>(t);
    }
    s.max_angle_deg = std::max(s.max_angle_deg, tq.max_angle_deg);
  }
  s.avg_q = sum_q / s.triangles;
  s.mean_min_angle_deg = sum_min_angle / s.triangles;
  s.pct_below_threshold = 100.0 * s.below_threshold / s.triangles;
  return s;
}

}  // namespace voroseal
