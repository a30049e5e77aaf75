// Mesh building (paper §3.2, Algorithms 2 and 3): the output surfaces as the dual of the
// connected components of the restricted Voronoi cells.
//
// Each restricted cell is split into connected components inside the surface parts (CC), and
// its restriction to the contacts into connected components along the contacts (BC, joined at
// the corners the cell holds). Output vertices (Algorithm 3):
//   - a BC gets one vertex: at its corner when it holds one, merged into one when it holds
//     several (Fig. 11b), else on the contact (length-weighted centroid projected on it);
//   - a CC touching no contact gets one vertex at its centroid, projected on its surface part;
//   - a CC touching more than two distinct contact vertices has them merged (Fig. 11a), or,
//     by default, keeps them and gets the polygon joining them;
//   - features closer than a minimum feature size d_min (Fig. 11c-d) are merged later, by the
//     clean-up, with edge collapses that keep the surfaces manifold (mesh_cleanup.h).
// Output polygons: every restricted Voronoi vertex where three cells meet inside a surface part
// gives a triangle between the vertices of the three components around it. A component with
// two vertices (it touches two contact components) is split in two halves across each chain of
// Voronoi edges between its contact arcs; the split edge gives a triangle or a quad with the
// neighbouring cell (the quads between close contacts, Fig. 10c-d), cut into triangles.
// Triangles keep the orientation of the surface part they remesh.
#pragma once

#include <string>
#include <vector>

#include "framework/model/structural_model.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

/// A change of the model's features made because the resolution is too coarse for them.
struct FeatureMerge {
  enum Reason {
    CornersInOneCell,          // corners linked by a contact inside one cell (Fig. 11b)
    ManyContactPoints,         // a cell component touching more than two contact pieces (Fig. 11a)
    CloseFeatures,             // features of one cell closer than the minimum feature size (Fig. 11c-d)
    Repair,                    // features closer than the resolution merged to undo a crossing or a leak
  };
  Reason reason;
  int seed = -1;
  Vec3 location = Vec3::Zero();          // local frame
  std::vector<VertexFeature> features;   // what was merged (corners, contacts, surfaces)
};

const char* to_string(FeatureMerge::Reason reason);

struct MeshBuildOptions {
  /// Paper Fig. 11a: merge the contact points of a cell component that touches more than two
  /// contact pieces. When false, such a component keeps its points and the polygon joining
  /// them (in boundary order) is added, which changes no feature.
  bool merge_many_contact_points = false;
  /// A contact vertex where the contact turns by more than `sharp_angle_deg`, measured between
  /// the chords to the points `sharp_scale` before and after it along the contact, is a feature
  /// the remesh keeps: a cell holding one puts its contact point there (a fault tip, the bend
  /// of a cut-off line). sharp_scale <= 0 disables it here; remesh() replaces 0 by half the mean
  /// edge length of the remesh (a negative value keeps it off).
  double sharp_scale = 0.0;
  double sharp_angle_deg = 50.0;
};

struct MeshBuildResult {
  RemeshedSurface surface;
  std::vector<FeatureMerge> merges;
  int cell_components = 0;
  int contact_components = 0;
  int junction_triangles = 0;       // from restricted Voronoi vertices
  int split_polygons = 0;           // from components with two contact vertices
  int degenerate_dropped = 0;       // polygons that lost a vertex to a merge
  int sharp_points = 0;             // contact points held at sharp bends
  int inconsistencies = 0;          // junctions whose neighbours could not be matched (expect 0)
  int open_boundaries = 0;          // component boundaries that did not close (expect 0)
};

/// Builds the output surfaces from the restricted Voronoi diagram of optimised seeds.
MeshBuildResult build_remeshed_surface(const StructuralModel& input, const ModelGeometry& geometry,
                                       const RestrictedVoronoiDiagram& rvd, const SurfaceProjector& projector,
                                       const MeshBuildOptions& options = {});

}  // namespace voroseal
