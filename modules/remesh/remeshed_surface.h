// RemeshedSurface: the output surfaces while the remesher builds and cleans them, before they
// become a StructuralModel again. Every vertex knows which input feature it samples (a surface
// part, a contact or a corner) so that it can be kept on it.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

struct VertexFeature {
  enum Kind : uint8_t { Surface = 0, Contact = 1, Corner = 2 };
  Kind kind = Surface;
  int id = -1;          // input surface part, contact or corner
  bool pinned = false;  // never moved: held at a sharp bend of its contact, or a fault tip joined to a part
                        // (bends of the fidelity refinement slide within its tolerance)
};

struct RemeshedSurface {
  std::vector<Vec3> vertices;            // local frame of the input model
  std::vector<VertexFeature> features;   // one per vertex
  std::vector<Triangle> triangles;
  std::vector<int> triangle_part;        // input surface part each triangle remeshes

  /// Drops vertices no triangle uses and renumbers the others.
  void remove_unused_vertices();
  /// Drops the triangles marked in `dead` (one flag per triangle), then the unused vertices.
  void remove_triangles(const std::vector<char>& dead);
};

}  // namespace voroseal
