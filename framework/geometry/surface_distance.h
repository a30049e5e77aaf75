// Distances between triangulated surfaces, for fidelity (design.md "Metrics"): the two-sided
// Hausdorff distance estimated on sample points, each point's distance to the other surface
// from a CGAL AABB tree (exact closest triangle, floating-point distance).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

/// Sample points of a triangle set: every vertex used by a triangle, every edge midpoint, then
/// area-weighted uniform random points (std::mt19937_64 from `seed`: reproducible on every
/// platform) until `total` points (no random points when the fixed ones reach it).
std::vector<Vec3> sample_surface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                 size_t total, uint64_t seed);

/// Distance queries to a fixed triangle set (an AABB tree built once; queries are thread-safe).
class TriangleSetDistance {
 public:
  /// \throws ModelError when a triangle refers to a vertex that does not exist.
  TriangleSetDistance(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);
  ~TriangleSetDistance();
  TriangleSetDistance(const TriangleSetDistance&) = delete;
  TriangleSetDistance& operator=(const TriangleSetDistance&) = delete;

  bool empty() const;
  /// Squared distance from p to the closest triangle (+inf when the set is empty).
  double squared_distance(const Vec3& p) const;
  /// Closest point of the triangle set to p. \pre !empty()
  Vec3 closest_point(const Vec3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

/// Distances from sample points of one surface to another.
struct OneSidedDistance {
  double max = 0, mean = 0, rms = 0;
  Vec3 max_at = Vec3::Zero();  // the sample farthest from the other surface
  size_t samples = 0;
};

/// Distances from every point of `samples` to `target`, in parallel. +inf when the target is empty.
/// `each`, when given, receives every sample's distance (in the order of `samples`).
OneSidedDistance one_sided_distance(const std::vector<Vec3>& samples,
                                    const TriangleSetDistance& target,
                                    std::vector<double>* each = nullptr);

struct HausdorffDistance {
  OneSidedDistance a_to_b, b_to_a;
  double hausdorff = 0;  // max(a_to_b.max, b_to_a.max)
};

/// Two-sided Hausdorff distance between triangle sets A and B (same frame), each sampled with
/// `samples_per_surface` points (sample_surface) and the seed.
HausdorffDistance hausdorff_distance(const std::vector<Vec3>& a_vertices, const std::vector<Triangle>& a_triangles,
                                     const std::vector<Vec3>& b_vertices, const std::vector<Triangle>& b_triangles,
                                     size_t samples_per_surface = 200000, uint64_t seed = 1);

}  // namespace voroseal
