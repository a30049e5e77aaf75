#include "framework/model/welding.h"

#include <cmath>
#include <unordered_map>

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

  const double cell = tolerance;
  const double tol2 = tolerance * tolerance;
  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  grid.reserve(points.size());
  auto cell_of = [&](const Vec3& p) {
    return std::array<long long, 3>{static_cast<long long>(std::floor(p.x() / cell)),
                                    static_cast<long long>(std::floor(p.y() / cell)),
                                    static_cast<long long>(std::floor(p.z() / cell))};
  };
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const auto c = cell_of(p);
    int found = -1;
    double best = tol2;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (int w : it->second) {
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
      grid[c].push_back(found);
    }
    result.representative[i] = found;
  }
  return result;
}

}  // namespace voroseal
