// Border gaps: where a surface's free border, past the corner at which it meets another
// surface, runs on just off that surface (a fault whose tip leaves another fault at a few
// degrees). The gap between them opens from the corner at that angle, and no contact marks it.
// Unlike a wedge between two surfaces it is open at the side, so it does not bound the tets:
// but tets across it are flat wherever its surfaces' triangles are wider than it is thick
// (the flattest tets of CloudSpin_fixed's remeshes lie in two such gaps).
#pragma once

#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

struct BorderGap {
  int apex = -1;          // the corner's model vertex, where the border meets the surface
  int vertex = -1;        // the border vertex where the gap is narrowest (the angle below)
  int border_part = -1;   // the part whose free border it is
  int surface_part = -1;  // the part the border runs along
  /// The gap's opening: asin(distance of `vertex` to the surface / its distance to the apex).
  double angle_deg = 0.0;
  /// The border from the apex (excluded) while it stays within the angle bound off the surface.
  std::vector<int> border;
};

/// The gaps narrower than `max_deg` degrees, narrowest first. From each end of each free
/// border, along the border while it stays under `max_deg` off each other part at that end.
std::vector<BorderGap> thin_border_gaps(const StructuralModel& model, double max_deg);

}  // namespace voroseal
