#include "framework/geometry/triangle_indices.h"

#include <string>

#include "framework/core/error.h"

namespace voroseal {

void check_triangle_indices(size_t vertex_count, const std::vector<Triangle>& triangles) {
  const long n = static_cast<long>(vertex_count);
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int v : triangles[t])
      if (v < 0 || v >= n)
        throw ModelError("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) + " of " +
                         std::to_string(n));
}

}  // namespace voroseal
