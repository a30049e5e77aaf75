// SurfaceSoup: triangulated surfaces as a file gives them, before any topology is inferred.
// Readers produce it; build_model() turns it into a StructuralModel.
#pragma once

#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"

namespace voroseal {

/// A named set of triangles: an OBJ group, a TSurf TFACE patch, a Medit triangle ref.
struct SurfaceGroup {
  std::string name;       // unique within the soup, e.g. "h1_model1/0"
  std::string interface;  // geological surface it belongs to (TSurf object name, OBJ group)
  SurfaceKind kind = SurfaceKind::Unknown;
  std::string feature;    // GOCAD GEOLOGICAL_FEATURE when given
};

/// A region listed explicitly by a file (GOCAD Model3d REGION): sides are signed 1-based group
/// indices (+k: the region is on the side group k's right-hand normal points to).
struct ExplicitRegion {
  std::string name;
  std::vector<int> signed_groups;
};

struct SurfaceSoup {
  std::string source;               // file name, for messages
  std::vector<Vec3> points;         // file coordinates, z up
  std::vector<Triangle> triangles;  // indices into points
  std::vector<int> triangle_group;  // index into groups, one per triangle
  std::vector<SurfaceGroup> groups;

  // Explicit structure (GOCAD Model3d). When `has_explicit_parts`, every group is exactly one
  // surface part (TFACE) and `regions` (universe included) and `layers` are authoritative.
  bool has_explicit_parts = false;
  std::vector<ExplicitRegion> regions;
  std::vector<std::pair<std::string, std::vector<int>>> layers;  // name, indices into regions
};

}  // namespace voroseal
