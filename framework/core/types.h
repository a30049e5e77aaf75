// Basic geometric types shared by every part of voroseal.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <limits>

namespace voroseal {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
/// Three vertex indices; the order gives the normal (right-hand rule).
using Triangle = std::array<int, 3>;
using Tetrahedron = std::array<int, 4>;

/// Axis-aligned bounding box.
struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return !(min.array() <= max.array()).all(); }
  Vec3 center() const { return 0.5 * (min + max); }
  double diagonal() const { return empty() ? 0.0 : (max - min).norm(); }
  /// Squared distance from x to the box (0 inside): no larger than to anything in it.
  double squared_distance(const Vec3& x) const {
    return ((min - x).cwiseMax(0.0) + (x - max).cwiseMax(0.0)).squaredNorm();
  }
};

}  // namespace voroseal
