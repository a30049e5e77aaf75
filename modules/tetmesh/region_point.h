// Region points: one point strictly inside each region of a StructuralModel, the "seed" TetGen
// needs to tell its regions apart (regionlist), and the membership test behind it.
#pragma once

#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"

namespace voroseal {

/// Generalized winding number of the signed sides `sides` at `p` (local frame): the sum of the
/// solid angles of their triangles over 4π, each counted with the side's sign. With the model's
/// side convention (the sides of a bounded region have their normals pointing into it) a point
/// inside the region gets −1, a point outside 0. A fault ending inside the region contributes
/// both of its sides, which cancel. Undefined when `p` lies on one of the triangles.
double winding_number(const StructuralModel& model, const std::vector<Side>& sides, const Vec3& p);

/// Where a region point came from, for reports and debugging.
struct RegionPoint {
  Vec3 point = Vec3::Zero();  // local frame
  double clearance = 0.0;     // distance to the nearest model triangle
  double winding = 0.0;       // winding number over the region's sides (≈ −1)
};

/// One point strictly inside each bounded region (same order as model.regions).
///
/// Candidates are offset from well-shaped side triangles (large area × quality) along the
/// normal direction into the region, to half the distance of the first surface the ray meets
/// and to a local-size offset; the candidate farthest from every model triangle whose winding
/// number over the region's sides is −1 wins. So the point is inside the region (winding) and
/// not on or near any surface (clearance).
/// \pre the model has regions; the sides of each region enclose it (a sealed model).
/// \throws ModelError naming the region when no candidate is inside it with a clearance above
///         1e-9 of the bounding-box diagonal (a region that is not closed, or of zero volume).
std::vector<RegionPoint> region_points(const StructuralModel& model);

}  // namespace voroseal
