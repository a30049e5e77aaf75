// StructuralModel: the surfaces of a 3D geological structural model and their connectivity.
//
// Vocabulary (Pellerin et al. 2014, Fig. 1):
//  - a *surface part* is a connected piece of a geological surface bounded by contacts;
//  - a *contact* is a polyline where two or more surface parts meet, or where one part has a
//    free border (a fault tip);
//  - a *corner* (triple point) ends contacts;
//  - a *region* is a volume bounded by *sides* of surface parts; the region outside the
//    model is the *universe*.
//
// Coordinates are stored in a local frame: file coordinates = local + frame.origin. Files use
// UTM-like coordinates (5e5, 4e6) where a float-sized relative error is metres; the origin is
// an integer point near the bbox centre, so local = file - origin is exact in double.
#pragma once

#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/surface_mesh.h"

namespace voroseal {

/// Geological nature of a surface (GOCAD GEOLOGICAL_TYPE / TFACE type).
enum class SurfaceKind { Unknown, Horizon, Fault, Boundary, Unconformity };

const char* to_string(SurfaceKind kind);
SurfaceKind surface_kind_from_string(const std::string& s);  // unknown names give Unknown

/// A geological interface: one named surface of the model (a GOCAD TSurf object, an OBJ group
/// family), made of one or more surface parts.
struct Interface {
  std::string name;
  SurfaceKind kind = SurfaceKind::Unknown;
  std::string feature;     // GOCAD GEOLOGICAL_FEATURE, empty when unknown
  std::vector<int> parts;  // indices into StructuralModel::parts
};

/// One surface part: a manifold, consistently oriented triangle mesh.
struct SurfacePart {
  std::string name;        // the group's name, "<group>.<k>" when a group gave several parts
  int interface = -1;      // index into StructuralModel::interfaces
  int source_group = -1;   // index of the SurfaceSoup group it was built from
  SurfaceMesh mesh;        // points in the local frame
  /// Model vertex id of each mesh vertex (mesh vertex i -> model_vertex[i]). A vertex that is
  /// non-manifold inside the part appears several times in the mesh with the same model id.
  std::vector<int> model_vertex;
  /// Index in the soup it was built from of each mesh face (face f -> source_triangle[f]).
  std::vector<int> source_triangle;
  std::vector<int> contacts;  // contacts on the border of or inside this part
};

/// A contact line: a polyline of model vertices between two corners (equal for a closed line).
struct Contact {
  std::vector<int> vertices;  // model vertex ids, from corners[0] to corners[1]
  std::vector<int> parts;     // incident surface parts, sorted, unique
  int incidence = 0;          // triangles incident to each edge of the contact (1 = free border)
  std::array<int, 2> corners{{-1, -1}};  // indices into StructuralModel::corners

  bool is_free_border() const { return incidence == 1; }
  bool is_closed() const { return vertices.size() > 2 && vertices.front() == vertices.back(); }
};

/// A corner (triple point): a model vertex where contacts end.
struct Corner {
  int vertex = -1;            // model vertex id
  std::vector<int> contacts;  // contacts ending here (a closed contact appears twice)
};

/// One side of a surface part: `positive` is the side the right-hand normal points to.
struct Side {
  int part = -1;
  bool positive = true;
  bool operator==(const Side& o) const { return part == o.part && positive == o.positive; }
  bool operator<(const Side& o) const {
    return part != o.part ? part < o.part : positive < o.positive;
  }
};

/// A volume bounded by sides of surface parts. A fault ending inside a region contributes both
/// of its sides to that region.
struct Region {
  std::string name;
  std::vector<Side> sides;
};

/// A stratigraphic layer or fault block: a named group of regions.
struct Layer {
  std::string name;
  std::vector<int> regions;
};

/// Local frame: file coordinates = local + origin.
struct Frame {
  Vec3 origin = Vec3::Zero();
};

/// What building the model from its file changed or noticed. The check module reports it:
/// cracks welded shut inside a surface, dropped triangles, inconsistent orientation.
struct BuildReport {
  std::string source;
  int input_points = 0;
  int input_triangles = 0;
  int merged_points = 0;                  // input points welded into an earlier one
  int degenerate_triangles_dropped = 0;   // a repeated vertex after welding
  int duplicate_triangles_dropped = 0;    // same three vertices as an earlier triangle
  /// Distinct input points of one group welded together: colocated vertices inside a surface.
  int colocated_points_in_group = 0;
  /// Manifold edges inside one group whose two triangles used different input points for the
  /// edge: a crack inside a surface that only welding closed.
  int sewn_edges_within_group = 0;
  /// Vertices where one group uses several distinct input points although no contact runs there
  /// along which the group lies on both sides (an internal border), or more than two points
  /// (RINGMesh's rule): a crack inside a surface, invisible once welded (CloudSpin.ml).
  int crack_vertices = 0;
  std::vector<std::string> cracked_groups;  // groups with sewn edges or crack vertices
  /// Groups with an edge of 3+ of their own triangles: several surfaces in one group (a Medit
  /// soup with all refs 0), where cracks cannot be told from contacts and are not searched.
  std::vector<std::string> multi_surface_groups;
  std::vector<Vec3> crack_locations;        // a few examples, local frame
  int inconsistent_orientation_edges = 0;   // explicit parts whose triangles disagree
  int flipped_triangles = 0;                // triangles reoriented to make a part consistent
  int split_vertices = 0;                   // non-manifold vertices inside one part, duplicated
  bool explicit_regions = false;            // regions read from the file (not inferred)
};

class StructuralModel {
 public:
  std::string name;
  Frame frame;
  std::vector<Vec3> vertices;  // unique (welded) vertices, local frame
  std::vector<Interface> interfaces;
  std::vector<SurfacePart> parts;
  std::vector<Contact> contacts;
  std::vector<Corner> corners;
  std::vector<Region> regions;  // bounded regions only
  Region universe;              // the outside: its sides face away from every region
  std::vector<Layer> layers;
  BuildReport build;  // provenance: how the model was built from its file

  int num_triangles() const;
  BoundingBox bbox() const;  // local frame
  double area() const;

  /// Regions on each side of every part: first = region on the positive side, second = on the
  /// negative side; -1 stands for the universe, -2 for "no region" (model without regions).
  std::vector<std::pair<int, int>> part_regions() const;
  /// Region adjacency graph: sorted neighbour lists (regions sharing a surface part).
  /// The universe is not listed.
  std::vector<std::vector<int>> region_adjacency() const;
  /// Signed volume enclosed by a set of sides (divergence theorem, local frame):
  /// -V for a bounded region with the side convention above, +V for the universe.
  double signed_volume(const std::vector<Side>& sides) const;
};

/// All triangles of a model, flattened: what hot loops (RVD, intersection tests) iterate on.
struct ModelTriangles {
  std::vector<Triangle> triangles;  // model vertex ids, oriented as in their part
  std::vector<int> part;            // surface part of each triangle
};
ModelTriangles flatten(const StructuralModel& model);
/// Appends the triangles of one part to `out`, as model vertex ids in mesh face order (what
/// flatten() does part by part).
void append_part_triangles(const SurfacePart& part, std::vector<Triangle>& out);

}  // namespace voroseal
