// VolumeMesh: a tetrahedral mesh with region ids, plus the boundary and interface triangles
// with surface ids (what TetGen produces from a StructuralModel).
#pragma once

#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"

namespace voroseal {

struct VolumeMesh {
  Frame frame;                      // file coordinates = local + frame.origin
  std::vector<Vec3> vertices;       // local frame
  std::vector<Tetrahedron> tets;    // positive orientation
  std::vector<int> tet_region;      // region id per tet (index into region_names)
  std::vector<Triangle> triangles;  // boundary and interface triangles
  std::vector<int> triangle_surface;  // surface id per triangle (index into surface_names)
  std::vector<std::string> region_names;
  std::vector<std::string> surface_names;
};

}  // namespace voroseal
