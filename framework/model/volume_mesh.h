// VolumeMesh: a tetrahedral mesh with region ids, plus the boundary and interface triangles
// with surface ids (what TetGen produces from a StructuralModel), and the model's contact
// lines and corners as edges and points of the mesh.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"

namespace voroseal {

using Edge = std::array<int, 2>;

struct VolumeMesh {
  Frame frame;                      // file coordinates = local + frame.origin
  std::vector<Vec3> vertices;       // local frame
  std::vector<Tetrahedron> tets;    // positive orientation
  std::vector<int> tet_region;      // region id per tet (index into region_names)
  std::vector<Triangle> triangles;  // boundary and interface triangles
  /// Surface id per triangle (index into surface_names): one id per input surface (the model's
  /// Interface, all its pieces together), what boundary conditions are set on.
  std::vector<int> triangle_surface;
  std::vector<std::string> region_names;
  std::vector<std::string> surface_names;
  std::vector<SurfaceKind> surface_kinds;  // one per surface name; shorter: the rest Unknown
  /// Piece of its surface per triangle (index into part_names: the model's surface parts);
  /// empty when the file did not say.
  std::vector<int> triangle_part;
  std::vector<std::string> part_names;
  /// Contact-line segments (mesh vertex ids) with a contact id each (index into contact_names):
  /// one id per set of surfaces meeting along the line, named after them ("F1+H1"; a free
  /// border, such as a fault tip, names its one surface).
  std::vector<Edge> edges;
  std::vector<int> edge_contact;
  std::vector<std::string> contact_names;
  /// Corner points (mesh vertex ids) with a corner id each (index into corner_names): one id per
  /// set of surfaces meeting there, named after them ("F1+H1+H2").
  std::vector<int> corners;
  std::vector<int> corner_id;
  std::vector<std::string> corner_names;

  /// The kind of surface `id` (Unknown past surface_kinds).
  SurfaceKind surface_kind(int id) const {
    return id >= 0 && id < static_cast<int>(surface_kinds.size()) ? surface_kinds[id]
                                                                  : SurfaceKind::Unknown;
  }
};

}  // namespace voroseal
