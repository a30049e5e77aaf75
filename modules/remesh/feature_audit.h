// Feature audit: which input surface parts, contacts and corners have no counterpart in the
// remeshed model, and whether each was smaller than the resolution (the remesher merges what one
// restricted Voronoi cell holds, paper Fig. 11) or not (a loss the user must hear about).
//
// A feature's size: a surface part's width (2 × area / perimeter: the width of a strip, the
// radius of a disc); a contact's length, or less: the width of the narrowest part it bounds (a
// thin strip merged away takes one of its two contacts with it), or how close it runs along
// another contact (the largest distance from its vertices to it); a corner's distance to the
// nearest other corner, or the size of its smallest contact if less.
#pragma once

#include <utility>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"
#include "modules/remesh/remeshed_surface.h"  // VertexFeature::Kind

namespace voroseal {

struct LostFeature {
  VertexFeature::Kind kind = VertexFeature::Surface;  // a surface part, a contact or a corner
  int id = -1;                                        // index in the input model
  double size = 0.0;                                  // see above, model units
  Vec3 location = Vec3::Zero();                       // a point of the feature, local frame
};

/// An input region without its own output region: thinner than a cell, or merged.
struct LostRegion {
  int region = -1;
  double thickness = 0.0;  // 2 × volume / area of its sides: a layer's thickness (a third of a cube's side)
  std::vector<Vec3> places;  // points spread over its sides, local frame: where to refine
};

/// Two input regions that no longer touch.
struct LostRegionContact {
  int a = -1, b = -1;
  double width = 0.0;  // of the widest input part between them
  std::vector<Vec3> places;  // points spread over the parts between them, local frame
};

struct FeatureAudit {
  /// What features are compared with: the diameter of a restricted Voronoi cell, 2h/√3 for a
  /// mean edge length h (a regular hexagon's); the paper's merges act within one cell.
  double resolution = 0.0;
  std::vector<LostFeature> lost;  // surface parts, then contacts, then corners
  /// Output features with no input counterpart (id: index in the output model; size 0): an
  /// input part remeshed as several, a contact or corner where the input has none.
  std::vector<LostFeature> gained;
  std::vector<LostRegion> regions_lost;
  std::vector<LostRegionContact> region_contacts_lost;
  /// Lost features, regions and region contacts at least as large as the resolution.
  int larger_than_resolution() const;
};

/// Compares `input` with its remeshed model `output`, whose part i remeshes input part
/// `input_part[i]`. A part survives with an output part remeshing it; a contact with an output
/// contact between the same input parts, a corner with an output corner where the same input
/// parts meet (as many as the input has: the largest are counted kept). Also sizes the input
/// regions `regions_lost` (input region ids) and the region contacts (pairs of input regions)
/// lost, found by the caller's region matching.
FeatureAudit audit_features(const StructuralModel& input, const StructuralModel& output,
                            const std::vector<int>& input_part, const std::vector<int>& regions_lost,
                            const std::vector<std::pair<int, int>>& region_contacts_lost, double resolution);

}  // namespace voroseal
