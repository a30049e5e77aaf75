// Smoothing of the interior points next to slivers. A point inside a region (on no surface
// triangle) that is a vertex of a tet flatter than a bound moves to where the smallest dihedral
// angle of its tets is largest, and stays there only when that angle rose and every one of its
// tets stays positive and within its volume bound. Only the moved point's tets change, so no
// tet ends flatter than the flattest of them was: the smallest angle of the mesh never drops,
// and the surfaces, the regions and the tets' connectivity stay as they are.
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
};

struct SliverSmoothingResult {
  long candidates = 0;  // interior points of tets below the bound, over all passes
  long moved = 0;       // moves kept
  int passes = 0;       // passes run (the last one moved nothing, or the limit was reached)
};

/// Moves the interior points of `mesh` next to its flat tets (see above); mesh.triangles tell
/// which points lie on surfaces. Parallel over sets of points that share no tet; the result
/// does not depend on the number of threads.
SliverSmoothingResult smooth_sliver_points(VolumeMesh& mesh, const SliverSmoothingOptions& options);

}  // namespace voroseal
