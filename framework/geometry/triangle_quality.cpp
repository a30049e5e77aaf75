#include "framework/geometry/triangle_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voroseal {

TriangleQuality measure_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* p[3] = {&a, &b, &c};
  double len[3], angle[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = *p[(k + 1) % 3] - *p[k], v = *p[(k + 2) % 3] - *p[k];
    len[k] = u.norm();  // edge k -> k+1
    angle[k] = std::atan2(u.cross(v).norm(), u.dot(v)) * (180.0 / M_PI);
  }
  TriangleQuality tq;
  tq.area = 0.5 * (b - a).cross(c - a).norm();
  const double h_max = std::max({len[0], len[1], len[2]});
  const double half_perimeter = 0.5 * (len[0] + len[1] + len[2]);
  tq.q = h_max > 0 ? 6.0 * tq.area / (std::sqrt(3.0) * h_max * half_perimeter) : 0.0;
  tq.min_angle_deg = std::min({angle[0], angle[1], angle[2]});
  tq.max_angle_deg = std::max({angle[0], angle[1], angle[2]});
  return tq;
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
