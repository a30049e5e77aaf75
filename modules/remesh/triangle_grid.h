// A uniform grid of triangle bounding boxes: the candidate pairs of the clean-up's local
// intersection tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

// Entries are only added; a triangle that moved is inserted again and stale entries are
// filtered by the caller (alive, actual bounding boxes).
class TriangleGrid {
 public:
  void reset(double cell) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    cells_.clear();
    big_.clear();
  }
  void insert(int t, const Vec3& lo, const Vec3& hi) {
    if (cell_count(lo, hi) > kMaxCells) {
      big_.push_back(t);
      return;
    }
    for_cells(lo, hi, [&](std::uint64_t k) { cells_[k].push_back(t); });
  }
  template <class F>
  void query(const Vec3& lo, const Vec3& hi, F&& f) const {
    for (int t : big_) f(t);
    if (cell_count(lo, hi) > kMaxCells) {
      for (const auto& [k, list] : cells_)
        for (int t : list) f(t);
      return;
    }
    for_cells(lo, hi, [&](std::uint64_t k) {
      auto it = cells_.find(k);
      if (it != cells_.end())
        for (int t : it->second) f(t);
    });
  }

 private:
  static constexpr double kMaxCells = 512;
  long index(double x) const { return static_cast<long>(std::floor(x * inv_)); }
  double cell_count(const Vec3& lo, const Vec3& hi) const {
    double n = 1;
    for (int d = 0; d < 3; ++d) n *= static_cast<double>(index(hi[d]) - index(lo[d]) + 1);
    return n;
  }
  template <class F>
  void for_cells(const Vec3& lo, const Vec3& hi, F&& f) const {
    const long x0 = index(lo.x()), x1 = index(hi.x()), y0 = index(lo.y()), y1 = index(hi.y()), z0 = index(lo.z()),
               z1 = index(hi.z());
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y)
        for (long z = z0; z <= z1; ++z)
          f((static_cast<std::uint64_t>(x & 0x1FFFFF) << 42) | (static_cast<std::uint64_t>(y & 0x1FFFFF) << 21) |
            static_cast<std::uint64_t>(z & 0x1FFFFF));
  }
  double inv_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<int> big_;
};

}  // namespace voroseal
