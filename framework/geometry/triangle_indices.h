// The precondition of every geometry routine that takes vertices and triangles by index.
#pragma once

#include <vector>

#include "framework/core/types.h"

namespace voroseal {

/// \throws ModelError naming the first triangle that refers to a vertex outside
/// [0, vertex_count).
void check_triangle_indices(size_t vertex_count, const std::vector<Triangle>& triangles);

}  // namespace voroseal
