// The steps of build_model() after parts are known (internal to framework/model).
#pragma once

#include <array>
#include <vector>

#include "framework/model/model_builder.h"
#include "framework/model/triangle_topology.h"

namespace voroseal {

/// Oriented triangles of the model with their surface part, and the edge table over them.
struct PartedTriangles {
  std::vector<Triangle> triangles;  // welded vertex ids, oriented consistently per part
  std::vector<int> part;
  EdgeTable edges;                  // line flags set
  /// Line edges that an explicit part (a Model3d TFACE) crosses without a border in the file:
  /// its two triangles there share the edge's input points. (a, b, part) with a < b, sorted.
  /// Filled for CornerRule::Incidence only: RINGMesh's Model3d loader does not count such a
  /// part among the surfaces of the line (see find_crossed_line_edges in model_builder.cpp).
  std::vector<std::array<int, 3>> crossed_line_edges;
};

/// Chains line edges into contacts between corners (rule: see CornerRule); fills
/// model.contacts, model.corners and every part's contact list.
void build_contacts(StructuralModel& model, const PartedTriangles& t, CornerRule rule);

/// Regions by radial sorting of the triangles around every line edge and gluing facing
/// sides; components that do not share a contact are nested with winding numbers.
/// Fills model.regions and model.universe.
void infer_regions(StructuralModel& model, const PartedTriangles& t);

}  // namespace voroseal
