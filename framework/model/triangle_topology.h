// Triangle-level topology shared by the steps of build_model() (internal to framework/model):
// edges with their incident triangles, and which edges are *line edges* (design.md: an edge
// with other than two incident triangles, or two triangles of different surface parts).
#pragma once

#include <vector>

#include "framework/core/types.h"

namespace voroseal {

struct EdgeTable {
  struct Edge {
    int a, b;        // vertex ids, a < b
    int first;       // incident triangles are incident[first, first + count)
    int count;
    bool line;       // a line edge: contacts run along these
  };
  std::vector<Edge> edges;
  std::vector<int> incident;

  /// Edges sorted by (a, b); the triangles incident to each edge in increasing order.
  static EdgeTable build(const std::vector<Triangle>& triangles);
  /// Index of edge (a, b) in either order, -1 when absent.
  int find(int a, int b) const;
};

/// True when triangle t traverses the directed edge a -> b.
inline bool has_directed_edge(const Triangle& t, int a, int b) {
  return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
}

}  // namespace voroseal
