// Triangle-level topology shared by the steps of build_model() (internal to framework/model):
// edges with their incident triangles, and which edges are *line edges* (design.md: an edge
// with other than two incident triangles, or two triangles of different surface parts).
#pragma once

#include <cmath>
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

/// One triangle around an edge (a, b): the angle of its third vertex about the axis a -> b.
struct FanBlade {
  double angle;  // radians in (-pi, pi], right-handed about a -> b
  int triangle;
  bool forward;  // the triangle traverses the edge a -> b (its normal is axis x (apex - a))
};

/// The triangles incident[0, count) around edge (a, b), sorted by angle (ties by index), into
/// `fan`. A forward triangle's positive side faces increasing angles, so the wedge between
/// fan[i] and fan[i + 1] (the last one wrapping around to fan[0]) lies between the side of
/// fan[i] facing increasing angles and the side of fan[i + 1] facing decreasing ones.
void radial_fan(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, int a, int b,
                const int* incident, int count, std::vector<FanBlade>& fan);

/// Angle (radians) of the wedge between fan[i] and the next blade, the last one wrapping around.
inline double wedge_after(const std::vector<FanBlade>& fan, size_t i) {
  return i + 1 < fan.size() ? fan[i + 1].angle - fan[i].angle : fan[0].angle + 2.0 * M_PI - fan[i].angle;
}

/// True when triangle t traverses the directed edge a -> b.
inline bool has_directed_edge(const Triangle& t, int a, int b) {
  return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
}

}  // namespace voroseal
