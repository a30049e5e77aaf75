// The topological ball property of a restricted Voronoi diagram on a structural model (seed
// paper §2.2.3, after Edelsbrunner and Shah 1997). The dual of the restricted cells is a
// faithful remesh where every restricted cell
//   - meets each surface part in one topological disk or not at all,
//   - meets each contact in one segment or not at all,
//   - holds at most one corner,
//   - and is one piece: its pieces on different parts are linked through the contacts they
//     share (a cell that reaches both sides of a thin layer, or two surfaces passing through
//     it without meeting there, is not).
// This file finds the cells where the property fails and, for each failure, a point on the
// model where one more seed splits the offending piece off, with the distance between the
// pieces that the failure would merge: below the minimum feature size the merge is deliberate.
#pragma once

#include <vector>

#include "framework/core/types.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/restricted_voronoi_diagram.h"

namespace voroseal {

struct BallViolation {
  enum Kind {
    NotADisk,       // a cell component inside a part with a hole (Euler characteristic != 1)
    PartPieces,     // a cell meeting one surface part in several components
    ContactPieces,  // a cell meeting one contact in several segments
    Corners,        // a cell holding several corners
    Unlinked,       // pieces of one cell on parts that do not meet inside it
  };
  Kind kind = NotADisk;
  int seed = -1;
  Vec3 where = Vec3::Zero();  // a point on the model (local frame) inside the offending piece
  /// Distance between the offending piece and the rest of the cell (the size of what the
  /// dual would merge); +inf for a hole.
  double separation = 0.0;
  double cell_size = 0.0;  // edge length of the dual around this cell: sqrt(area / (√3/2))
  /// Unlinked: the surface parts of the largest offending piece and of the cell's largest
  /// piece (-1 for the other kinds).
  int part = -1, other_part = -1;
};

const char* to_string(BallViolation::Kind kind);

/// Every failure of the topological ball property in `rvd`, in seed order.
std::vector<BallViolation> find_ball_violations(const ModelGeometry& geometry,
                                                const RestrictedVoronoiDiagram& rvd,
                                                int threads = 0);

}  // namespace voroseal
