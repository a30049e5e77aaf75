// Pockets: output regions that are no input region of their own. Where two surfaces come closer
// than the resolution (a layer pinching out, a fault whose throw fades, a horizon meeting a fault
// at a low angle), the remeshed surfaces can touch along a loop away from their input contact and
// close a thin volume between them. The paper's d_min merge (Fig. 11c-d) merges such surfaces
// where their contacts come close; a pocket is what is left where they come close without a
// contact nearby. A pocket goes by removing sides: the two surfaces then are one there, as they
// are in the input beyond the contact (the pinch-out, the fault tip).
#pragma once

#include <string>
#include <vector>

#include "framework/model/structural_model.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

/// Sides removed from a pocket.
struct PocketRemoval {
  std::string region;      // the input region the pocket joined (empty: another pocket)
  std::vector<std::string> parts;  // the output surface parts removed
  double volume = 0.0;     // of the pocket
  double thickness = 0.0;  // 2V/A
  double neck = 0.0;       // widest input gap along its rim, where its sides meet
  int triangles = 0;       // removed
  std::vector<std::string> relabeled;  // "output part -> input part" for the sides relabelled
  Vec3 location = Vec3::Zero();  // middle of the removed parts, local frame of `surface`
};

/// Opens the pockets of `output` (the model built from `surface`, its regions matched to the
/// input's by `output_region_of_input`) thinner than `resolution` (2V/A) by removing sides from
/// `surface`, the first that applies of:
///  - a bubble inside one region Q (Q beyond every side): every side goes;
///  - a side between the pocket and another pocket goes (one pocket, opened next round);
///  - one side between the pocket and a region Q goes, when every other side comes from an input
///    part facing Q's input region on that side (the model stays one the input's labels
///    describe), or lies within `resolution` / 2 of an input part that faces Q's region and the
///    same region beyond (it becomes that part: the wedge between a horizon and a fault pinched
///    off at its tip joins the region beyond the horizon, and the fault piece around it becomes
///    the fault part there).
/// A pocket thinner than `min_feature` (d_min) that none of these opens is a layer pinched
/// off on purpose: a side between it and an input region goes even though the other sides keep
/// their labels (a lens of a thin layer cut off by its two horizons touching joins the region
/// beyond one of them). So does a pocket of any thickness whose rim (where its sides meet) lies
/// where the input surfaces of those sides are closer than d_min: the merges below d_min cut it
/// off (a layer thinning to a sliver between a lens and the rest of it).
/// Nothing is removed that would leave an edge with a single triangle. Pockets with no such side
/// are left (and reported as gained regions). `input_part_of_output` gives the input part of
/// each output part.
std::vector<PocketRemoval> remove_pockets(RemeshedSurface& surface, const StructuralModel& input,
                                          const StructuralModel& output, const std::vector<int>& input_part_of_output,
                                          const std::vector<int>& output_region_of_input,
                                          const SurfaceProjector& projector, double resolution,
                                          double min_feature);

}  // namespace voroseal
