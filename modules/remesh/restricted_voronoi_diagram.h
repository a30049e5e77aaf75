// The restricted Voronoi diagram (RVD) of the seeds on the input model (paper §2.2.1, §3.2):
// the contract between seed optimisation and mesh building.
//
// For every seed i and every input triangle t its Voronoi cell meets, the diagram holds the
// clipped convex polygon V_i ∩ t, tagged with its triangle and surface part, with vertices in
// the orientation of the triangle. Every polygon vertex and edge says symbolically what made
// it, so the diagram's combinatorics are exact:
//
//   vertex kinds (RvdVertexTag)
//     InputVertex        {v}           a vertex of the input model (model vertex id v)
//     EdgeBisector       {a, b, i, j}  bisector of seeds i < j  ∩  input edge (a < b)
//     TriangleBisectors  {t, i, j, k}  bisectors of seeds i < j < k  ∩  triangle t (a restricted
//                                      Voronoi vertex inside a triangle; dual to triangle ijk)
//   edge supports (RvdEdgeTag, edge m goes from vertex m to vertex m+1 of the polygon)
//     bisector edge      neighbour = j      on the bisector of the polygon's seed and seed j
//     input edge         a < b, contact     on input edge (a, b); contact >= 0 when it is a line
//                                           edge of that contact (a contact line or free border)
//
// Equal tags are the same point. The positions of EdgeBisector vertices are bit-identical in
// every polygon that has them (computed from the edge in increasing vertex-id order); the
// positions of TriangleBisectors vertices agree to rounding. Distinct tags are distinct points
// except in exact degeneracies (a bisector through an input vertex, four co-circular seeds).
//
// Gluing: two polygons of the same seed in triangles sharing a non-line input edge (a, b) both
// have an edge on (a, b), and it is the same segment (same end tags): the cell meets the edge
// in one segment. Union over such edges gives the connected components of each restricted cell
// inside the surface parts (restricted_cell_components()). Across a line edge the cell goes on
// in other surface parts; its restriction to the contact is listed as contact segments.
//
// Contact restriction: for each seed, the segments V_i ∩ (line edge (a, b)) of every contact,
// each reported once whatever the number of triangles sharing the line edge, with tagged end
// points (InputVertex or EdgeBisector). Corners: the corners (triple points) that lie in each
// cell (each corner is in exactly one cell).
//
// Ties: a point equidistant from two seeds belongs to the one of lower index, so the polygons
// partition the model; of coincident seeds only the lowest index has a non-empty cell.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "framework/core/types.h"
#include "modules/remesh/model_geometry.h"

namespace voroseal {

/// What made a polygon vertex (see the file comment). Hashable; equal tags <=> same point.
struct RvdVertexTag {
  enum Kind : std::uint8_t { InputVertex = 0, EdgeBisector = 1, TriangleBisectors = 2 };
  Kind kind = InputVertex;
  /// InputVertex {v, -1, -1, -1}; EdgeBisector {a, b, i, j} with a < b, i < j;
  /// TriangleBisectors {t, i, j, k} with i < j < k (t: triangle index in flatten() order).
  std::array<int, 4> id{{-1, -1, -1, -1}};

  static RvdVertexTag input_vertex(int v) { return {InputVertex, {{v, -1, -1, -1}}}; }
  static RvdVertexTag edge_bisector(int a, int b, int i, int j);
  static RvdVertexTag triangle_bisectors(int t, int i, int j, int k);

  bool operator==(const RvdVertexTag& o) const { return kind == o.kind && id == o.id; }
  bool operator!=(const RvdVertexTag& o) const { return !(*this == o); }
  bool operator<(const RvdVertexTag& o) const { return kind != o.kind ? kind < o.kind : id < o.id; }
};

struct RvdVertexTagHash {
  size_t operator()(const RvdVertexTag& t) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL * (t.kind + 1);
    for (int x : t.id) h = (h ^ static_cast<std::uint32_t>(x)) * 0x100000001b3ULL + (h >> 29);
    return static_cast<size_t>(h);
  }
};

/// What a polygon edge lies on.
struct RvdEdgeTag {
  int neighbour = -1;  // >= 0: the bisector of the polygon's seed and this seed
  int a = -1, b = -1;  // input edge (a < b, model vertex ids) when neighbour < 0
  int contact = -1;    // contact of that input edge when it is a line edge, else -1

  bool on_bisector() const { return neighbour >= 0; }
  bool on_input_edge() const { return neighbour < 0; }
  bool on_line() const { return contact >= 0; }
  bool operator==(const RvdEdgeTag& o) const {
    return neighbour == o.neighbour && a == o.a && b == o.b && contact == o.contact;
  }
};

/// V_seed ∩ triangle: vertices [first, first + size) of the diagram's vertex arrays.
struct RvdPolygon {
  int seed = -1;
  int triangle = -1;  // flatten() index of the input triangle
  int part = -1;      // its surface part
  int first = 0;
  int size = 0;
};

/// A piece of a seed's cell on a contact: V_seed ∩ line edge (a, b).
struct RvdContactSegment {
  int seed = -1;
  int contact = -1;
  int a = -1, b = -1;           // the line edge, a < b (model vertex ids)
  std::array<Vec3, 2> end;      // end[0] is the end nearer a
  std::array<RvdVertexTag, 2> end_tag;  // InputVertex or EdgeBisector
};

struct RestrictedVoronoiDiagram {
  std::vector<Vec3> seeds;  // local frame

  /// Polygons sorted by (seed, triangle); those of seed i are
  /// [seed_polygons[i], seed_polygons[i + 1]).
  std::vector<RvdPolygon> polygons;
  std::vector<int> seed_polygons;
  /// Per polygon vertex, in polygon order (polygon p owns [first, first + size)); edge_tag[m]
  /// is the edge from vertex m to the next vertex of the same polygon.
  std::vector<Vec3> vertex;
  std::vector<RvdVertexTag> vertex_tag;
  std::vector<RvdEdgeTag> edge_tag;

  /// Contact segments sorted by (seed, contact, a, b); those of seed i are
  /// [seed_segments[i], seed_segments[i + 1]).
  std::vector<RvdContactSegment> segments;
  std::vector<int> seed_segments;

  /// Corners (indices into StructuralModel::corners) in each cell, sorted:
  /// corners[seed_corners[i] .. seed_corners[i + 1]).
  std::vector<int> corners;
  std::vector<int> seed_corners;

  int num_seeds() const { return static_cast<int>(seeds.size()); }
  /// Area of polygon p.
  double polygon_area(int p) const;
};

struct RvdOptions {
  int threads = 0;      // OpenMP threads, 0: default
  int neighbours = 16;  // length of the cached k-nearest lists
};

/// Computes the full restricted Voronoi diagram of `seeds` (local frame) on `geometry`.
/// Precondition: seeds finite. Never throws on degenerate input (zero-area or needle triangles,
/// coincident seeds): those give zero-area polygons or empty cells.
RestrictedVoronoiDiagram compute_restricted_voronoi_diagram(const ModelGeometry& geometry,
                                                            const std::vector<Vec3>& seeds,
                                                            const RvdOptions& options = {});

/// Connected components of every restricted cell inside the surface parts: polygons of one
/// seed glued across the non-line input edges they share. Returns the component of every
/// polygon (numbered from 0 over the whole diagram, components of seed i before those of i+1)
/// and sets *count to their number.
std::vector<int> restricted_cell_components(const RestrictedVoronoiDiagram& rvd, int* count = nullptr);

}  // namespace voroseal
