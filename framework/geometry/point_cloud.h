// A nanoflann k-d tree over an array of points: the seeds' neighbour lists (seed_neighbours)
// and the layer sizing's radius searches (layer_sizing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <nanoflann.hpp>

#include "framework/core/types.h"

namespace voroseal {

// nanoflann's dataset interface over `count` points; no precomputed bounding box.
struct PointCloud {
  const Vec3* points = nullptr;
  size_t count = 0;
  size_t kdtree_get_point_count() const { return count; }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using PointKdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                        PointCloud, 3, std::uint32_t>;

}  // namespace voroseal
