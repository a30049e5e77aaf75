// Smoothing of the points next to slivers. A point that is a vertex of a tet flatter than a
// bound moves to where the smallest dihedral angle of its tets is largest, and stays there only
// when that angle rose and every one of its tets stays positive and within its volume bound.
// Nor may a move raise the largest radius-edge ratio of those tets past kKeptRadiusEdge (or what
// it was). Only the moved point's tets change, so no tet ends flatter than the flattest of them
// was: the smallest angle of the mesh never drops, and the regions and the connectivity stay.
//
// Points inside the regions move freely. Points on the surfaces slide along them (when
// surface_slide > 0): a point inside a surface part on its triangles as they were, a point on a
// contact along its two contact edges; corners and other points where contacts meet stay. A
// slide is kept only when the new surface triangles lie within surface_slide × the mean edge at
// the point of the triangles as they were, and keep their smallest angle (or kKeptAngleDeg):
// the surfaces keep their shape, their triangles are placed for the tets.
#pragma once

#include <vector>

#include "framework/model/volume_mesh.h"

namespace voroseal {

struct SliverSmoothingOptions {
  /// The points of the tets whose smallest dihedral angle is below this (degrees) are moved.
  double below_deg = 15.0;
  /// Passes over those points (each pass finds them again: a move changes its neighbours').
  int passes = 3;
  /// The largest volume a tet of region r may reach, region_volume_bound[r]; 0 or absent: none.
  std::vector<double> region_volume_bound;
  /// How far the surfaces may move, relative to the mean edge at a sliding point; 0 keeps the
  /// surface points where they are.
  double surface_slide = 0.0;
  /// What a move raises: the smallest dihedral angle of the point's tets (false), or (true) how
  /// far they fall under below_deg in all, the smallest angle of them never dropping: the tets
  /// under the bound rise even where the flattest of them cannot.
  bool deficit = false;
  /// When > 0, a move may not add to the tets of the point flatter than this (degrees): the
  /// flattest rise without others falling under it.
  double kept_count_below_deg = 0.0;
  /// The vertices the slide is measured from: surface points slide on the triangles of these
  /// positions, within surface_slide of them. Empty: the mesh's vertices as they are. A second
  /// smoothing gets the vertices from before the first, so the slides do not add up.
  std::vector<Vec3> reference;
};

struct SliverSmoothingResult {
  long candidates = 0;     // points of tets below the bound, over all passes
  long moved = 0;          // points inside the regions moved
  long moved_surface = 0;  // points on the surfaces slid
  int passes = 0;          // passes run (the last one moved nothing, or the limit was reached)
};

/// Moves the points of `mesh` next to its flat tets (see above). The surfaces are
/// mesh.triangles, their parts triangle_part (triangle_surface when it is empty): an edge whose
/// triangles are not two of one part is on a contact. Parallel over sets of points that share
/// no tet; the result does not depend on the number of threads.
SliverSmoothingResult smooth_sliver_points(VolumeMesh& mesh, const SliverSmoothingOptions& options);

}  // namespace voroseal
