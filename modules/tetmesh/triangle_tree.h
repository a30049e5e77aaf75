// TriangleTree: distance, ray and segment queries against a set of triangles (a CGAL AABB tree
// behind a small interface), used to place points strictly inside regions.
#pragma once

#include <memory>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

class TriangleTree {
 public:
  /// Indexes `triangles` (ids into `points`); degenerate (collinear) triangles are left out.
  /// The arguments are copied: they may be destroyed afterwards.
  TriangleTree(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);
  ~TriangleTree();
  TriangleTree(const TriangleTree&) = delete;
  TriangleTree& operator=(const TriangleTree&) = delete;

  /// True when every triangle was degenerate.
  bool empty() const;
  /// Distance from p to the nearest triangle (+inf when empty).
  double distance(const Vec3& p) const;
  /// Distance from `origin` along the unit direction `direction` to the first triangle met,
  /// ignoring triangle `skip` (an index into the constructor's list, −1 for none); +inf when
  /// the ray meets none, 0 when it runs inside a coplanar triangle.
  double ray_hit(const Vec3& origin, const Vec3& direction, int skip = -1) const;
  /// True when the closed segment [a, b] meets a triangle.
  bool segment_hits(const Vec3& a, const Vec3& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voroseal
