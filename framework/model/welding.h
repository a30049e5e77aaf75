// Welding: merging vertices that coincide up to a tolerance.
#pragma once

#include <vector>

#include "framework/core/types.h"

namespace voroseal {

struct WeldResult {
  std::vector<int> representative;  // for each input point, the index of its welded vertex
  std::vector<int> source;          // for each welded vertex, the input point kept (first seen)
};

/// Merges points closer than `tolerance` (absolute) to the first point of their cluster, in
/// input order, with a hash grid of cell size `tolerance`. Chains are not followed: a point
/// joins the first kept point within `tolerance`, so the result does not depend on a
/// transitive closure that could drift along a line of close points.
/// `tolerance` = 0 merges exactly equal points only.
WeldResult weld_points(const std::vector<Vec3>& points, double tolerance);

}  // namespace voroseal
