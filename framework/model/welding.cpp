#include "framework/model/welding.h"

#include <cmath>
#include <unordered_map>
#include <vector>

namespace voroseal {

namespace {

struct CellHash {
  size_t operator()(const std::array<long long, 3>& c) const {
    // Large primes mix the three cell coordinates (Teschner et al. 2003).
    return static_cast<size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};

}  // namespace

WeldResult weld_points(const std::vector<Vec3>& points, double tolerance) {
  WeldResult result;
  result.representative.resize(points.size());
  if (tolerance <= 0.0) {
    struct PointHash {
      size_t operator()(const Vec3& p) const {
        return std::hash<double>()(p.x()) ^ (std::hash<double>()(p.y()) * 31) ^ (std::hash<double>()(p.z()) * 131);
      }
    };
    struct PointEq {
      bool operator()(const Vec3& a, const Vec3& b) const { return a == b; }
    };
    std::unordered_map<Vec3, int, PointHash, PointEq> seen;
    seen.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      auto [it, inserted] = seen.emplace(points[i], static_cast<int>(result.source.size()));
      if (inserted) result.source.push_back(static_cast<int>(i));
      result.representative[i] = it->second;
    }
    return result;
  }

  // Cells twice the tolerance wide: the points within it of p lie in the two cells per axis on
  // p's side of its cell's middle, 8 cells to search rather than 27.
  const double cell = 2.0 * tolerance;
  const double tol2 = tolerance * tolerance;
  // Kept points by cell: the first in `head`, the others chained through `next`.
  std::unordered_map<std::array<long long, 3>, int, CellHash> head;
  head.reserve(points.size());
  std::vector<int> next;
  next.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    std::array<long long, 3> c, low;
    for (int k = 0; k < 3; ++k) {
      const double u = p[k] / cell, f = std::floor(u);
      c[k] = static_cast<long long>(f);
      low[k] = c[k] - (u - f < 0.5 ? 1 : 0);
    }
    int found = -1;
    double best = tol2;
    for (long long dx = 0; dx <= 1; ++dx)
      for (long long dy = 0; dy <= 1; ++dy)
        for (long long dz = 0; dz <= 1; ++dz) {
          const auto it = head.find({low[0] + dx, low[1] + dy, low[2] + dz});
          if (it == head.end()) continue;
          for (int w = it->second; w >= 0; w = next[w]) {
            const double d2 = (points[result.source[w]] - p).squaredNorm();
            if (d2 <= best && (found < 0 || d2 < best || w < found)) {
              best = d2;
              found = w;
            }
          }
        }
    if (found < 0) {
      found = static_cast<int>(result.source.size());
      result.source.push_back(static_cast<int>(i));
      const auto [it, inserted] = head.emplace(c, found);
      next.push_back(inserted ? -1 : it->second);
      if (!inserted) it->second = found;
    }
    result.representative[i] = found;
  }
  return result;
}

}  // namespace voroseal
